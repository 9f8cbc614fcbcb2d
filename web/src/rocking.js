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

/** The error of a run given up for a newer one (`superseded` is true). */
function superseded() {
  return Object.assign(new Error("superseded by a newer run"), { superseded: true });
}

/**
 * Runs scenarios one at a time in a Web Worker, the newest first: a request
 * made while another waits replaces it (the waiting one rejects, superseded);
 * one made while a run has taken over LONG_MS ends that run (its worker is
 * ended and a new one started) rather than wait for it. The page's main
 * thread never runs the engine, whatever the duration.
 */
class Runner {
  static LONG_MS = 250;

  constructor() {
    this.worker = null;
    this.current = null;
    this.queued = null;
    this.id = 0;
  }

  run(scenario) {
    return this.request({ scenario: JSON.stringify(scenario) });
  }

  /** history.csv of the last run (a Blob), made by the worker that holds its every row. */
  historyCsv() {
    if (this.busy) return Promise.reject(new Error("history.csv: the run is not over yet"));
    return this.request({ csv: true });
  }

  request(message) {
    return new Promise((resolve, reject) => {
      if (this.queued) this.queued.reject(superseded());
      this.queued = { id: ++this.id, message, resolve, reject, start: 0 };
      if (this.current && performance.now() - this.current.start > Runner.LONG_MS) {
        this.worker.terminate();
        this.worker = null;
        this.current.reject(superseded());
        this.current = null;
      }
      this.pump();
    });
  }

  /** Whether a run is under way or waiting. */
  get busy() {
    return !!(this.current || this.queued);
  }

  pump() {
    if (this.current || !this.queued) return;
    const job = (this.current = this.queued);
    this.queued = null;
    if (!this.worker) {
      this.worker = new Worker(new URL("./run-worker.js", import.meta.url), { type: "module" });
      this.worker.onmessage = ({ data }) => this.finish(data);
      this.worker.onerror = (e) => this.finish({ id: this.current?.id, error: e.message || "the run's worker failed" });
    }
    job.start = performance.now();
    this.worker.postMessage({ id: job.id, ...job.message });
  }

  finish(data) {
    const job = this.current;
    if (!job || job.id !== data.id) return;
    this.current = null;
    if (data.error !== undefined) job.reject(new Error(data.error));
    else job.resolve(data.result);
    this.pump();
  }
}

const runner = new Runner();

/**
 * Runs a scenario in a Web Worker: a Promise of { summary, derived, history,
 * rows, stride, regimeNames, events, eventColumns, chart, slips }: the
 * history's columns as Float64Arrays (the regime as a Uint8Array of indices
 * into regimeNames), every row of it, or for a history of over 200,000 rows
 * every `stride`-th row and the last (all `rows` are in historyCsv()); the
 * derived quantities of check(); the charts' series (thinned to about 4,000
 * points for long runs: each span's extremes) and the sliding spans [t0, t1].
 * The newest call wins: an older one still waiting or long under way rejects
 * with an Error whose `superseded` is true.
 */
function runInWorker(scenario) {
  return runner.run(scenario);
}

/** The response spectrum of the scenario's record (see crates/rocking-web, recordSpectrum): { periods_s, psa_g, pga_g, … }. */
function recordSpectrum(scenario, dampingPct = 5) {
  return JSON.parse(call(engine.recordSpectrum, JSON.stringify(scenario), dampingPct));
}

/** The kinematic part of `rocking assess` for an assessment file's table: its assessment.json, plus the capacity curve. */
function assess(table) {
  return JSON.parse(call(engine.assess, JSON.stringify(table)));
}

export const rocking = {
  ready,
  run,
  runInWorker,
  /** history.csv of the last runInWorker() (a Promise of a Blob). */
  historyCsv: () => runner.historyCsv(),
  check,
  recordSpectrum,
  assess,
  sweep,
  fromToml,
  toToml,
  sweepableKeys: () => ready.then(() => JSON.parse(engine.sweepableKeys())),
  /** Every key's description, as `rocking keys --json` prints it: { scenario: [{ key, unit, symbol, … }], assessment: […] }. */
  keys: () => ready.then(() => JSON.parse(engine.keys())),
  /** The summary's fields as the outputs reference describes them: [{ name, unit, meaning }]. */
  summaryFields: () => ready.then(() => JSON.parse(engine.summaryFields())),
  /** The derived quantities of check() described: [{ name, unit, meaning }]. */
  derivedFields: () => ready.then(() => JSON.parse(engine.derivedFields())),
};
window.rocking = rocking;
