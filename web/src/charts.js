// The time histories, as in the command's figures: θ/α with a_g (in g), the
// building's slip, the top's displacement; impacts as vertical lines and slip
// intervals shaded. uPlot draws 10^4-point series in a few milliseconds.
import uPlot from "../vendor/uPlot.esm.js";

/** Contiguous [t0, t1] spans where the building slides (regime sliding or rocking_sliding). */
function slipIntervals(h) {
  const spans = [];
  let start = null;
  for (let i = 0; i < h.t.length; i++) {
    const sliding = h.regime[i] === "sliding" || h.regime[i] === "rocking_sliding";
    if (sliding && start === null) start = h.t[i];
    if (!sliding && start !== null) {
      spans.push([start, h.t[i]]);
      start = null;
    }
  }
  if (start !== null) spans.push([start, h.t[h.t.length - 1]]);
  return spans;
}

function markers(state) {
  return {
    hooks: {
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

export class Charts {
  constructor(container) {
    this.container = container;
    this.state = { impacts: [], slips: [] };
    this.plots = null;
  }

  create(width) {
    const plugin = [markers(this.state)];
    const common = { width, height: 240, plugins: plugin, legend: { live: false }, cursor: { sync: { key: "t" } } };
    const axisX = { label: "t (s)" };
    this.plots = [
      new uPlot(
        {
          ...common,
          title: "θ/α and ground acceleration (red lines: impacts; shaded: sliding)",
          scales: { x: { time: false }, g: { auto: true } },
          series: [
            {},
            { label: "θ/α", stroke: "#1f4e99", width: 1.5 },
            { label: "a_g (g)", stroke: "rgba(60, 160, 60, 0.7)", width: 1, scale: "g" },
            { label: "a_v (g)", stroke: "rgba(204, 121, 167, 0.8)", width: 1, scale: "g", show: false },
          ],
          axes: [axisX, { label: "θ/α" }, { scale: "g", side: 1, label: "a_g (g)", grid: { show: false } }],
        },
        [[], [], [], []],
        this.container,
      ),
      new uPlot(
        { ...common, title: "slip of the building", scales: { x: { time: false } }, series: [{}, { label: "slip (m)", stroke: "#c06010", width: 1.5 }], axes: [axisX, { label: "slip (m)" }] },
        [[], []],
        this.container,
      ),
      new uPlot(
        { ...common, title: "top displacement relative to the building", scales: { x: { time: false } }, series: [{}, { label: "top_dx (m)", stroke: "#2a7a2a", width: 1.5 }], axes: [axisX, { label: "top_dx (m)" }] },
        [[], []],
        this.container,
      ),
    ];
  }

  update(result) {
    if (!this.plots) this.create(Math.max(360, Math.min(900, this.container.clientWidth || 700)));
    const h = result.history;
    const alpha = result.summary.alpha_rad;
    this.state.impacts = result.events.filter((e) => e.kind === "impact").map((e) => e.t);
    this.state.slips = slipIntervals(h);
    // a_g in g: the scenario's g (from the derived quantities), set by the page.
    const gravity = result.gravity;
    const ratio = alpha ? h.theta.map((x) => x / alpha) : h.theta.map(() => null);
    // The vertical acceleration (with [ground.vertical]) on the same axis as a_g.
    const vertical = h.ground_acc_v ? h.ground_acc_v.map((a) => a / gravity) : h.t.map(() => null);
    this.plots[0].setData([h.t, ratio, h.ground_acc.map((a) => a / gravity), vertical]);
    this.plots[0].setSeries(3, { show: !!h.ground_acc_v });
    this.plots[1].setData([h.t, h.slip]);
    this.plots[2].setData([h.t, h.top_dx]);
  }
}
