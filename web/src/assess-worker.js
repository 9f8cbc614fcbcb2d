// The assess tab's Web Worker: the capacity and the kinematic checks of
// `rocking assess` (each check scans ag in steps of 1e-4 g: tens of
// milliseconds), and a hazard grid's site parameters, off the main thread.
import init, { assess, gridSite } from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });

onmessage = async ({ data }) => {
  try {
    await ready;
    const start = performance.now();
    const text = data.kind === "grid" ? gridSite(data.grid, data.lon, data.lat, data.VN, data.CU) : assess(data.table);
    postMessage({ id: data.id, result: JSON.parse(text), ms: performance.now() - start });
  } catch (e) {
    postMessage({ id: data.id, error: e && e.message ? e.message : String(e) });
  }
};
