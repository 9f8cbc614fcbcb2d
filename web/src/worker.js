// The sweep's Web Worker: runs the cases in blocks of about 50 ms so that the
// page shows progress and stays responsive; the page ends the worker to cancel.
import init, { WebSweep } from "../pkg/rocking_web.js";

onmessage = async ({ data }) => {
  try {
    await init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });
    const sweep = new WebSweep(data.scenario, data.axes);
    const length = sweep.length;
    postMessage({ header: JSON.parse(sweep.header()), csvHeader: sweep.csvHeader(), length, done: false });
    let block = 1;
    for (let start = 0; start < length; ) {
      const end = Math.min(length, start + block);
      const t0 = performance.now();
      const { rows, csv } = JSON.parse(sweep.runCases(start, end));
      const took = performance.now() - t0;
      // Aim at ~50 ms per block: fewer messages for fast cases, steady progress for slow ones.
      block = Math.max(1, Math.min(4096, Math.round((block * 50) / Math.max(took, 1))));
      start = end;
      postMessage({ rows, csv, length, done: start >= length });
    }
    if (length === 0) postMessage({ rows: [], csv: "", length, done: true });
  } catch (e) {
    postMessage({ error: e && e.message ? e.message : String(e) });
  }
};
