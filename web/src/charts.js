// The time histories, as in the command's figures: θ/α with a_g (in g), the
// building's slip, the top's displacement; impacts as vertical lines and slip
// intervals shaded. uPlot draws 10^4-point series in a few milliseconds.
import uPlot from "../vendor/uPlot.esm.js";

function markers(state) {
  return {
    hooks: {
      // The y range in use, on the chart's element (what a reader sees on its axis).
      setScale: [
        (u, key) => {
          if (key === "y") u.root.dataset.yRange = JSON.stringify([u.scales.y.min, u.scales.y.max]);
        },
      ],
      drawClear: [
        (u) => {
          const { ctx, bbox } = u;
          ctx.save();
          ctx.fillStyle = "rgba(230, 140, 20, 0.18)";
          for (const [a, b] of state.slips) {
            const x0 = u.valToPos(a, "x", true);
            const x1 = u.valToPos(b, "x", true);
            ctx.fillRect(x0, bbox.top, Math.max(1, x1 - x0), bbox.height);
          }
          ctx.restore();
        },
      ],
      draw: [
        (u) => {
          const { ctx, bbox } = u;
          ctx.save();
          ctx.strokeStyle = "rgba(200, 30, 30, 0.3)";
          ctx.lineWidth = 1;
          ctx.beginPath();
          for (const t of state.impacts) {
            const x = Math.round(u.valToPos(t, "x", true)) + 0.5;
            ctx.moveTo(x, bbox.top);
            ctx.lineTo(x, bbox.top + bbox.height);
          }
          ctx.stroke();
          ctx.restore();
        },
      ],
    },
  };
}

/** A tick's text: 3 significant digits, in exponent form below 10⁻³ (no 0.0000012 over the axis label). */
export function tickText(v) {
  if (v === 0) return "0";
  return Math.abs(v) < 1e-3 || Math.abs(v) >= 1e5 ? v.toExponential(1) : String(Number(v.toPrecision(3)));
}

/**
 * A y scale's range: uPlot's own for a quantity that varies; around the
 * value for a constant one (an all-zero slip gets −1 … 1, not 0 … 100).
 */
export function yRange(u, min, max) {
  if (min === null || max === null || !Number.isFinite(min) || !Number.isFinite(max)) return [-1, 1];
  if (min === max) {
    const pad = Math.abs(min) * 0.1 || 1;
    return [min - pad, max + pad];
  }
  return uPlot.rangeNum(min, max, 0.1, true);
}

/** A y axis labelled `label`, wide enough for its ticks' texts (so that the label never overlaps them). */
export function yAxis(label, extra = {}) {
  return {
    label,
    values: (u, splits) => splits.map(tickText),
    size: (u, values) => 18 + 7 * Math.max(3, ...(values || []).map((v) => String(v).length)),
    ...extra,
  };
}

export class Charts {
  /** The θ/α chart goes into `first`, the slip's and the top's into `rest`. */
  constructor(first, rest) {
    this.first = first;
    this.container = rest;
    this.state = { impacts: [], slips: [] };
    this.plots = null;
    // The blocks' chart (with [[block]] tables): remade when the blocks change.
    this.blockPlot = null;
    this.blockNames = "";
    new ResizeObserver(() => this.resize()).observe(rest);
  }

  widths() {
    return [this.first, this.container].map((c) => Math.max(240, Math.min(900, c.clientWidth || 700)));
  }

  resize() {
    if (!this.plots) return;
    const [w0, w1] = this.widths();
    this.plots.forEach((p, k) => p.width !== (k ? w1 : w0) && p.setSize({ width: k ? w1 : w0, height: p.height }));
    if (this.blockPlot && this.blockPlot.width !== w1) this.blockPlot.setSize({ width: w1, height: this.blockPlot.height });
  }

  /**
   * θ/α of each block on the tower (its rotation relative to the block below
   * over its own α, from the check's `blocks`), the tower's with them; none
   * without blocks.
   */
  updateBlocks(result) {
    const blocks = result.derived.blocks || [];
    const names = blocks.map((b) => b.name).join(",");
    if (names !== this.blockNames) {
      this.blockPlot?.destroy();
      this.blockPlot = null;
      this.blockNames = names;
      if (!blocks.length) return;
      const colours = ["#b5634b", "#7a3d99", "#2a7a2a", "#c06010", "#444"];
      this.blockPlot = new uPlot(
        {
          height: 240,
          width: this.widths()[1],
          plugins: [markers(this.state)],
          legend: { live: false },
          cursor: { sync: { key: "t" } },
          title: "θ/α of each block on the block below (each its own α; red lines: the tower's impacts)",
          scales: { x: { time: false }, y: { range: yRange } },
          series: [{}, { label: "tower θ/α", stroke: "#1f4e99", width: 1 }, ...blocks.map((b, k) => ({ label: `${b.name} θ/α`, stroke: colours[k % colours.length], width: 1.5 }))],
          axes: [{ label: "t (s)" }, yAxis("θ/α")],
        },
        [[], [], ...blocks.map(() => [])],
        this.container,
      );
    }
    if (!this.blockPlot) return;
    const h = result.chart;
    const alpha = result.summary.alpha_rad;
    const series = blocks.map((b) => Array.from(h[`${b.name}_theta`], (x) => x / b.alpha_rad));
    this.blockPlot.setData([Array.from(h.t), Array.from(h.theta, (x) => (alpha ? x / alpha : null)), ...series]);
    const s = result.summary;
    const peaks = blocks.map((b) => `${b.name} peak ${tickText(s[`${b.name}_max_theta_over_alpha`] ?? 0)}, ${s[`${b.name}_impacts`] ?? 0} impacts`).join("; ");
    const canvas = this.blockPlot.root.querySelector("canvas");
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", `θ/α of each block on the block below against time: ${peaks}.`);
  }

  create() {
    const [w0, w1] = this.widths();
    const plugin = [markers(this.state)];
    const common = { height: 240, plugins: plugin, legend: { live: false }, cursor: { sync: { key: "t" } } };
    const axisX = { label: "t (s)" };
    const y = { range: yRange };
    this.plots = [
      new uPlot(
        {
          ...common,
          width: w0,
          title: "θ/α and ground acceleration (red lines: impacts; shaded: sliding)",
          scales: { x: { time: false }, y, g: { range: yRange } },
          series: [
            {},
            { label: "θ/α", stroke: "#1f4e99", width: 1.5 },
            { label: "a_g (g)", stroke: "rgba(60, 160, 60, 0.7)", width: 1, scale: "g" },
            { label: "a_v (g)", stroke: "rgba(204, 121, 167, 0.8)", width: 1, scale: "g", show: false },
          ],
          axes: [axisX, yAxis("θ/α"), yAxis("a_g (g)", { scale: "g", side: 1, grid: { show: false } })],
        },
        [[], [], [], []],
        this.first,
      ),
      new uPlot(
        { ...common, width: w1, title: "slip of the building", scales: { x: { time: false }, y }, series: [{}, { label: "slip (m)", stroke: "#c06010", width: 1.5 }], axes: [axisX, yAxis("slip (m)")] },
        [[], []],
        this.container,
      ),
      new uPlot(
        { ...common, width: w1, title: "top displacement relative to the building", scales: { x: { time: false }, y }, series: [{}, { label: "top_dx (m)", stroke: "#2a7a2a", width: 1.5 }], axes: [axisX, yAxis("top_dx (m)")] },
        [[], []],
        this.container,
      ),
    ];
  }

  update(result) {
    if (!this.plots) this.create();
    // The series as the run's worker thinned them for drawing (rocking.runInWorker).
    const h = result.chart;
    const alpha = result.summary.alpha_rad;
    this.state.impacts = result.events.filter((e) => e.kind === "impact").map((e) => e.t);
    this.state.slips = result.slips;
    // a_g in g: the scenario's g (from the derived quantities), set by the page.
    const gravity = result.gravity;
    const ratio = Array.from(h.theta, (x) => (alpha ? x / alpha : null));
    // The vertical acceleration (with [ground.vertical]) on the same axis as a_g.
    const vertical = Array.from(h.ground_acc_v || h.t, (a) => (h.ground_acc_v ? a / gravity : null));
    const t = Array.from(h.t);
    this.plots[0].setData([t, ratio, Array.from(h.ground_acc, (a) => a / gravity), vertical]);
    this.plots[0].setSeries(3, { show: !!h.ground_acc_v });
    this.plots[1].setData([t, Array.from(h.slip)]);
    this.plots[2].setData([t, Array.from(h.top_dx)]);
    // Each chart's text alternative: what it shows and its extremes.
    const s = result.summary;
    const text = [
      `θ/α against time: peak ${tickText(s.max_theta_over_alpha ?? 0)}; ${this.state.impacts.length} impacts; ground acceleration in g.`,
      `Slip of the building against time: peak ${tickText(s.max_abs_slip_m ?? 0)} m, final ${tickText(s.final_slip_m ?? 0)} m.`,
      `Top displacement relative to the building against time: peak ${tickText(s.max_top_displacement_m ?? 0)} m.`,
    ];
    this.plots.forEach((p, k) => {
      const canvas = p.root.querySelector("canvas");
      canvas.setAttribute("role", "img");
      canvas.setAttribute("aria-label", text[k]);
    });
    this.updateBlocks(result);
  }
}
