// window.rocking: the engine (WebAssembly, crates/rocking-web) behind the API
// of the README's "The page in the browser". Every call takes and gives plain
// objects; the engine takes and gives JSON text (one parse per call is faster
// than building objects field by field across the boundary, and exact: every
// number is printed in its shortest form that reads back to the same double).
import init, * as engine from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) }).then(() => undefined);

/** Calls the engine; its error (a JsError) becomes an Error with the command's one line. */
function call(f, ...args) {
  try {
    return f(...args);
  } catch (e) {
    throw new Error(e && e.message ? e.message : String(e));
  }
}

/** Runs a scenario: { summary, history, events, eventColumns }, as summary.json, history.csv (columns), events.csv (rows, and its header). */
function run(scenario) {
  const start = performance.now();
  const output = call(engine.runColumns, JSON.stringify(scenario));
  try {
    // The float columns come as Float64Arrays (a copy, no printing and parsing), made plain arrays here.
    const { summary, events, event_columns, order, columns, text } = JSON.parse(output.meta());
    // history.csv's columns in its order: the numeric ones from their typed arrays, the text ones (regime) as given.
    const history = {};
    for (const name of order) history[name] = name in text ? text[name] : Array.from(output.column(columns.indexOf(name)));
    summary.wall_time_s = (performance.now() - start) / 1000;
    return { summary, history, events, eventColumns: event_columns };
  } finally {
    output.free();
  }
}

/** The derived quantities of `rocking check` (α, R, p, r, thresholds, the ground motion). */
function check(scenario) {
  return JSON.parse(call(engine.check, JSON.stringify(scenario)));
}

/** A TOML file's text as a scenario object (a syntax error throws the command's line). */
function fromToml(text) {
  return JSON.parse(call(engine.tomlToJson, text));
}

/** A scenario object as the text of a TOML file. */
function toToml(scenario) {
  return call(engine.jsonToToml, JSON.stringify(scenario));
}

/**
 * Runs a sweep in a Web Worker: a Promise of the sweep.csv columns ({ key: [values] },
 * null for an empty cell), with the CSV text itself as the non-enumerable property `csv`.
 * `axes` is the [sweep] table: { "ground.frequency": { from, to, steps }, "ground.amplitude": [0.5, 1] }.
 * Options: onProgress(done, total); signal (an AbortSignal) to cancel (the Promise then rejects).
 */
function sweep(scenario, axes, options = {}) {
  return new Promise((resolve, reject) => {
    const worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    let header = null;
    const rows = [];
    let csv = "";
    const finish = (f, value) => {
      worker.terminate();
      if (options.signal) options.signal.removeEventListener("abort", abort);
      f(value);
    };
    const abort = () => finish(reject, new Error("sweep cancelled"));
    if (options.signal) {
      if (options.signal.aborted) return abort();
      options.signal.addEventListener("abort", abort);
    }
    worker.onerror = (e) => finish(reject, new Error(e.message || "the sweep's worker failed"));
    worker.onmessage = ({ data }) => {
      if (data.error !== undefined) return finish(reject, new Error(data.error));
      if (data.header) {
        header = data.header;
        csv = data.csvHeader + "\n";
      }
      if (data.rows) {
        rows.push(...data.rows);
        csv += data.csv;
      }
      if (options.onProgress) options.onProgress(rows.length, data.length);
      if (data.done) {
        const columns = {};
        header.forEach((name, j) => (columns[name] = rows.map((r) => r[j])));
        Object.defineProperty(columns, "csv", { value: csv, enumerable: false });
        finish(resolve, columns);
      }
    };
    worker.postMessage({ scenario: JSON.stringify(scenario), axes: JSON.stringify(axes) });
  });
}

export const rocking = {
  ready,
  run,
  check,
  sweep,
  fromToml,
  toToml,
  sweepableKeys: () => ready.then(() => JSON.parse(engine.sweepableKeys())),
};
window.rocking = rocking;
