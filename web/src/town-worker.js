// The town tab's Web Worker: the towers of a CSV assessed as `rocking
// inventory` assesses them (crates/rocking-web's WebTown, the library's
// inventory), off the main thread. The kinematic checks of every tower are
// one message; with a record set, the towers go one at a time and each one
// finished is told (the page's progress bar); the page ends the worker to cancel.
import init, { WebTown } from "../pkg/rocking_web.js";

const ready = init({ module_or_path: new URL("../pkg/rocking_web_bg.wasm", import.meta.url) });

onmessage = async ({ data }) => {
  try {
    await ready;
    const start = performance.now();
    const town = new WebTown(data.assess, data.origin, data.towers, data.towersName, data.grid ?? undefined, data.gridName ?? undefined, JSON.stringify(data.records));
    const total = town.length;
    const step = data.records.length > 0 ? 1 : Math.max(1, total);
    let done = 0;
    while (done < total) {
      done = town.advance(step);
      if (done < total) postMessage({ id: data.id, progress: done, total });
    }
    postMessage({ id: data.id, result: { town: JSON.parse(town.town()), csv: town.csv(), header: JSON.parse(town.header()) }, ms: performance.now() - start });
    town.free();
  } catch (e) {
    postMessage({ id: data.id, error: e && e.message ? e.message : String(e) });
  }
};
