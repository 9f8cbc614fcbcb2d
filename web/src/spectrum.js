// A record's response spectrum beside its time history: when the scenario's
// ground is a record, the record as the run reads it (in g) and its
// pseudo-acceleration spectrum (in g, log-log, 0.02–4 s, the damping chosen),
// computed in a Web Worker by the engine of `rocking spectrum` (Nigam &
// Jennings, exact for the piecewise-linear record): the same numbers as the
// command for the same record. spectrum.csv is the command's file.
import uPlot from "../vendor/uPlot.esm.js";
import { tickText, yAxis, yRange } from "./charts.js";

/** A number as the command prints it in its lines: `sig` digits, trailing zeros dropped. */
export function sig(x, digits) {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return "0";
  const exponent = Math.floor(Math.log10(Math.abs(x)));
  if (exponent >= -4 && exponent < 6) {
    const text = x.toFixed(Math.max(0, digits - 1 - exponent));
    return text.includes(".") ? text.replace(/0+$/, "").replace(/\.$/, "") : text;
  }
  const [mantissa, exp] = x.toExponential(digits - 1).split("e");
  const m = mantissa.includes(".") ? mantissa.replace(/0+$/, "").replace(/\.$/, "") : mantissa;
  return `${m}e${Number(exp)}`;
}

/** A log axis's tick texts: it leaves some of its splits unlabelled (null). */
const logTicks = (u, splits) => splits.map((v) => (v == null ? "" : tickText(v)));

export class SpectrumView {
  /**
   * `box`: the element that holds the view (hidden without a record); in it,
   * #record-chart, #spectrum-chart, #spectrum-damping, #spectrum-text and
   * the spectrum.csv button (data-spectrum-download).
   */
  constructor(box) {
    this.box = box;
    this.damping = box.querySelector("#spectrum-damping");
    this.text = box.querySelector("#spectrum-text");
    this.worker = null;
    this.id = 0;
    this.scenario = null;
    this.name = "record";
    this.result = null;
    this.plots = null;
    this.damping.addEventListener("change", () => this.request());
    box.querySelector("[data-spectrum-download]").addEventListener("click", () => this.download());
    new ResizeObserver(() => this.resize()).observe(box);
  }

  /** After a run: the record of `scenario` (the horizontal one), named `name`; hidden if the ground is not a record. */
  update(scenario, name) {
    const ground = scenario.ground;
    const isRecord = ground && ground.type === "record" && typeof ground.text === "string";
    this.box.hidden = !isRecord;
    if (!isRecord) {
      this.scenario = null;
      return;
    }
    const text = JSON.stringify(scenario);
    // The file's name, as the command names the record's column.
    this.name = (name || "record").split("/").pop();
    if (text === this.scenario && this.result) return;
    this.scenario = text;
    this.request();
  }

  /** The damping field's value, or an error shown beside it (null). */
  readDamping() {
    const raw = this.damping.value.trim();
    const value = raw === "" ? 5 : Number(raw);
    return Number.isFinite(value) ? value : null;
  }

  request() {
    if (!this.scenario) return;
    const damping = this.readDamping();
    if (damping === null) return this.showError("damping: must be a number (% of critical)");
    if (!this.worker) {
      this.worker = new Worker(new URL("./spectrum-worker.js", import.meta.url), { type: "module" });
      this.worker.onmessage = ({ data }) => this.receive(data);
    }
    this.box.dataset.state = "computing";
    this.worker.postMessage({ id: ++this.id, scenario: this.scenario, damping });
  }

  receive(data) {
    if (data.id !== this.id) return;
    if (data.error !== undefined) return this.showError(data.error);
    this.showError("");
    this.result = data.result;
    // Kept on the element too, for the page's tests.
    this.box.spectrumResult = data.result;
    this.draw();
    this.box.dataset.state = "done";
  }

  /** An error at the damping field (aria-invalid, the message beside it), or none. */
  showError(message) {
    const note = this.box.querySelector("#spectrum-error");
    note.textContent = message.replace(/^damping: /, "");
    note.hidden = !message;
    if (message) {
      this.damping.setAttribute("aria-invalid", "true");
      this.damping.setAttribute("aria-describedby", "spectrum-error");
      this.box.dataset.state = "error";
      this.box.classList.add("stale");
    } else {
      this.damping.removeAttribute("aria-invalid");
      this.damping.removeAttribute("aria-describedby");
      this.box.classList.remove("stale");
    }
  }

  widths() {
    const w = this.box.clientWidth || 700;
    // Side by side when there is room for two charts of 320 px, else one above the other.
    const each = w >= 680 ? Math.floor((w - 16) / 2) : w;
    return Math.max(240, Math.min(700, each));
  }

  resize() {
    if (!this.plots || this.box.hidden) return;
    const w = this.widths();
    for (const p of this.plots) if (p.width !== w) p.setSize({ width: w, height: p.height });
  }

  create() {
    const w = this.widths();
    const legend = { live: false };
    this.plots = [
      new uPlot(
        {
          width: w,
          height: 240,
          title: "The record: ground acceleration as the run reads it",
          legend,
          scales: { x: { time: false }, y: { range: yRange } },
          series: [{}, { label: "a_g (g)", stroke: "rgba(60, 160, 60, 0.9)", width: 1 }],
          axes: [{ label: "t (s)" }, yAxis("a_g (g)")],
        },
        [[], []],
        this.box.querySelector("#record-chart"),
      ),
      new uPlot(
        {
          width: w,
          height: 240,
          title: "Its response spectrum (pseudo-acceleration)",
          legend,
          // The periods' own span (0.02–4 s), not the decades around it.
          scales: { x: { time: false, distr: 3, range: (u, min, max) => [min, max] }, y: { distr: 3 } },
          series: [{}, { label: "PSA (g)", stroke: "#1f4e99", width: 2 }],
          axes: [{ label: "T (s)", values: logTicks }, yAxis("PSA (g)", { values: logTicks })],
        },
        [[], []],
        this.box.querySelector("#spectrum-chart"),
      ),
    ];
  }

  draw() {
    const r = this.result;
    if (!this.plots) this.create();
    this.plots[0].setData([r.t_s, r.a_g]);
    // The legend names the damping.
    const legend = [...this.plots[1].root.querySelectorAll(".u-legend .u-series .u-label")].pop();
    if (legend) legend.textContent = `PSA (g), ${r.damping_pct}% damping`;
    // A log axis has no place for 0 (an all-zero record): such points are left out.
    this.plots[1].setData([r.periods_s, r.psa_g.map((v) => (v > 0 ? v : null))]);
    const line =
      `${this.name}: PGA ${sig(r.pga_g, 4)} g at t = ${sig(r.pga_time_s, 4)} s, ` +
      `peak PSA ${sig(r.peak_psa_g, 4)} g at T = ${sig(r.peak_period_s, 3)} s (${r.damping_pct}% damping)`;
    this.text.textContent = line;
    const labels = [
      `The record, a_g (g) against t (s): ${r.t_s.length} samples over ${sig(r.t_s[r.t_s.length - 1] ?? 0, 4)} s, PGA ${sig(r.pga_g, 4)} g.`,
      `Its pseudo-acceleration spectrum, PSA (g) against T (s), log-log over 0.02–4 s, ${r.damping_pct}% damping: peak ${sig(r.peak_psa_g, 4)} g at T = ${sig(r.peak_period_s, 3)} s.`,
    ];
    this.plots.forEach((p, k) => {
      const canvas = p.root.querySelector("canvas");
      canvas.setAttribute("role", "img");
      canvas.setAttribute("aria-label", labels[k]);
    });
    this.resize();
  }

  /** spectrum.csv as `rocking spectrum` writes it: period_s and the record's PSA in g. */
  csv() {
    const r = this.result;
    if (!r) return "";
    const column = /[",\n]/.test(this.name) ? `"${this.name.replace(/"/g, '""')}"` : this.name;
    return `period_s,${column}\n` + r.periods_s.map((t, k) => `${t},${r.psa_g[k]}`).join("\n") + "\n";
  }

  download() {
    const text = this.csv();
    if (!text) return;
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([text], { type: "text/csv" }));
    a.download = "spectra.csv";
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
}
