// The response spectrum's Web Worker: the spectrum of a long record (10⁵
// samples × 100 periods) takes a moment, which the page does not wait for.
import init, { recordSpectrum } from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });

onmessage = async ({ data }) => {
  try {
    await ready;
    postMessage({ id: data.id, result: JSON.parse(recordSpectrum(data.scenario, data.damping)) });
  } catch (e) {
    postMessage({ id: data.id, error: e && e.message ? e.message : String(e) });
  }
};
