// The single run's Web Worker: runs a scenario off the page's main thread and
// hands back the history as typed arrays (transferred, not copied: a copy
// of every row, or of every k-th of a long run, the whole kept here), the
// regime as one byte per row, the charts' series thinned to what a chart can
// show, and the sliding spans: whatever the duration, the page only draws.
import init, { runColumns, check } from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });

/** Rows above which the page gets every k-th row of the history (for the animation) rather than all of them. */
const FRAME_ROWS = 200000;
/** Rows above which a chart gets the extremes of each of CHART_BUCKETS spans instead of every row. */
const CHART_ROWS = 20000;
const CHART_BUCKETS = 2000;

/**
 * The series thinned for a chart: in each of `buckets` runs of rows, the
 * first and last instants with each series' minimum and maximum (in the order
 * they occur), so that every peak a pixel column holds is drawn.
 */
export function thin(t, series, buckets) {
  const n = t.length;
  if (n <= CHART_ROWS) return { t: Float64Array.from(t), series: series.map((s) => Float64Array.from(s)) };
  const size = Math.ceil(n / buckets);
  const count = Math.ceil(n / size);
  const outT = new Float64Array(2 * count);
  const out = series.map(() => new Float64Array(2 * count));
  for (let b = 0; b < count; b++) {
    const lo = b * size;
    const hi = Math.min(n, lo + size);
    outT[2 * b] = t[lo];
    outT[2 * b + 1] = t[hi - 1];
    series.forEach((s, j) => {
      let min = lo;
      let max = lo;
      for (let i = lo + 1; i < hi; i++) {
        if (s[i] < s[min]) min = i;
        if (s[i] > s[max]) max = i;
      }
      out[j][2 * b] = s[Math.min(min, max)];
      out[j][2 * b + 1] = s[Math.max(min, max)];
    });
  }
  return { t: outT, series: out };
}

/** Contiguous [t0, t1] spans where the building slides (regime sliding or rocking_sliding). */
function slipSpans(t, codes, names) {
  const sliding = names.map((n) => n === "sliding" || n === "rocking_sliding");
  const spans = [];
  let start = null;
  for (let i = 0; i < t.length; i++) {
    const s = sliding[codes[i]];
    if (s && start === null) start = t[i];
    if (!s && start !== null) {
      spans.push([start, t[i]]);
      start = null;
    }
  }
  if (start !== null) spans.push([start, t[t.length - 1]]);
  return spans;
}

/** The last run's whole history, for history.csv. */
let kept = null;

/** history.csv of the last run, as a Blob made of chunks of lines. */
function historyCsv() {
  if (!kept) throw new Error("no run to write");
  const { history, regimeNames } = kept;
  const names = Object.keys(history);
  const parts = [names.join(",") + "\n"];
  const n = history.t.length;
  for (let start = 0; start < n; start += 10000) {
    let chunk = "";
    for (let i = start; i < Math.min(n, start + 10000); i++) {
      chunk += names.map((c) => (c === "regime" ? regimeNames[history.regime[i]] : String(history[c][i]))).join(",") + "\n";
    }
    parts.push(chunk);
  }
  return new Blob(parts, { type: "text/csv" });
}

function run(text) {
  const start = performance.now();
  const derived = JSON.parse(check(text));
  const output = runColumns(text);
  try {
    const { summary, events, event_columns, order, columns, text: textColumns, blocks } = JSON.parse(output.meta());
    const history = {};
    let regimeNames = [];
    for (const name of order) {
      if (name in textColumns) {
        // One byte per row: its index in the list of the names met.
        const values = textColumns[name];
        const codes = new Uint8Array(values.length);
        const index = new Map();
        values.forEach((v, i) => {
          if (!index.has(v)) index.set(v, index.size);
          codes[i] = index.get(v);
        });
        history[name] = codes;
        if (name === "regime") regimeNames = [...index.keys()];
      } else {
        history[name] = output.column(columns.indexOf(name));
      }
    }
    summary.wall_time_s = (performance.now() - start) / 1000;
    const h = history;
    const names = ["theta", "ground_acc", "slip", "top_dx", ...(h.ground_acc_v ? ["ground_acc_v"] : []), ...blocks.map((b) => `${b}_theta`)];
    const { t, series } = thin(h.t, names.map((c) => h[c]), CHART_BUCKETS);
    const chart = { t };
    names.forEach((c, j) => (chart[c] = series[j]));
    const slips = h.regime ? slipSpans(h.t, h.regime, regimeNames) : [];
    // The whole history stays here (for history.csv); the page gets a copy
    // of it (what is transferred leaves this thread), of every k-th row and
    // the last for a long one.
    kept = { history, regimeNames };
    const rows = h.t.length;
    const stride = Math.max(1, Math.ceil(rows / FRAME_ROWS));
    const picks = Array.from({ length: Math.ceil(rows / stride) }, (_, k) => k * stride);
    if (picks[picks.length - 1] !== rows - 1) picks.push(rows - 1);
    const frames = {};
    for (const [name, column] of Object.entries(history)) frames[name] = stride > 1 ? column.constructor.from(picks, (i) => column[i]) : column.slice();
    const transfer = [...Object.values(frames).map((c) => c.buffer), t.buffer, ...series.map((s) => s.buffer)];
    const message = { summary, derived, history: frames, rows, stride, regimeNames, events, eventColumns: event_columns, chart, slips, blocks };
    return { message, transfer };
  } finally {
    output.free();
  }
}

onmessage = async ({ data }) => {
  try {
    await ready;
    if (data.csv) return postMessage({ id: data.id, result: historyCsv() });
    const { message, transfer } = run(data.scenario);
    postMessage({ id: data.id, result: message }, transfer);
  } catch (e) {
    postMessage({ id: data.id, error: e && e.message ? e.message : String(e) });
  }
};
