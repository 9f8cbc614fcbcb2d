// The dynamic checks' Web Worker: `rocking assess` with a record set (the
// record files' texts with their names), every record run through the model
// at each λ, here one after the other; its progress posted at most every
// 100 ms, and the runs done with the result. The page ends the worker to cancel.
import init, { assessDynamic } from "../pkg/rocking_web.js";

onmessage = async ({ data }) => {
  try {
    await init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });
    const start = performance.now();
    let last = -Infinity;
    let runs = 0;
    const progress = (done, most) => {
      runs = done;
      const now = performance.now();
      if (now - last < 100) return;
      last = now;
      postMessage({ progress: done, most });
    };
    const result = JSON.parse(assessDynamic(data.table, progress));
    postMessage({ result, ms: performance.now() - start, runs });
  } catch (e) {
    postMessage({ error: e && e.message ? e.message : String(e) });
  }
};
