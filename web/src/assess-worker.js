// The assess tab's Web Worker: the capacity and the kinematic checks of
// `rocking assess` (each check scans ag in steps of 1e-4 g: tens of
// milliseconds) with each check's name and formula and the capacity's
// quantities described, and a hazard grid's site
// parameters, off the main thread.
import init, { assess, capacityQuantities, checkTexts, gridSite } from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });

onmessage = async ({ data }) => {
  try {
    await ready;
    const start = performance.now();
    let result;
    if (data.kind === "grid") result = JSON.parse(gridSite(data.grid, data.lon, data.lat, data.VN, data.CU));
    else {
      result = JSON.parse(assess(data.table));
      const q = JSON.parse(data.table).assessment?.q;
      result.texts = JSON.parse(checkTexts(typeof q === "number" ? q : undefined));
      result.quantities = JSON.parse(capacityQuantities());
    }
    postMessage({ id: data.id, result, ms: performance.now() - start });
  } catch (e) {
    postMessage({ id: data.id, error: e && e.message ? e.message : String(e) });
  }
};
