// The town tab: every bell tower of a towers' CSV (one row each: id, name,
// lon, lat, and any key of the assessment file as a column) assessed as
// `rocking inventory` assesses them, from one of the examples' assessment
// files with its hazard grid, or from the user's own with the grid file it
// names (each tower's site from the grid at its lon, lat). The kinematic checks run as soon as the file is chosen; with record
// files chosen, the dynamic checks run in the worker, a tower at a time, with
// a progress bar. The map (lon/lat, coloured by the governing ζ_E) and the
// ranking (least ζ_E first) show the rows of the command's inventory.csv,
// which downloads as it is (and inventory.geojson).
import { assessments, grids, towns } from "../examples.js";
import { colour } from "./heatmap.js";
import { sig } from "./spectrum.js";

const $ = (id) => document.getElementById(id);
const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);

/** The top of the colour scale: the largest ζ_E, within these bounds (as the command's map). */
const TOP_BOUNDS = [1.2, 3.0];
/** Towers named on the map (the least ζ_E first). */
const NAMED_ON_MAP = 40;
/** The example town's file, chosen at first. */
const EXAMPLE_TOWN = "examples/town/towers.csv";

export class TownView {
  constructor(panel) {
    this.panel = panel;
    this.built = false;
    this.worker = null;
    this.id = 0;
    this.towers = null; // { name, text } of the towers' CSV
    this.records = []; // [{ name, text }] of the record set
    this.own = null; // { name, text } of the user's own assessment file, in place of an example's
    this.grid = null; // { name, text } of the hazard grid the user's own file names
    this.result = null;
  }

  show(visible) {
    if (visible && !this.built) this.build();
  }

  build() {
    this.built = true;
    const withGrid = assessments.filter((a) => a.grid);
    const first = Math.max(0, withGrid.findIndex((a) => a.path === "examples/town/assess.toml"));
    this.assessments = withGrid;
    this.panel.innerHTML = `
      <h2>A town's bell towers</h2>
      <p class="note">Each row of a towers' CSV (<code>id</code>, <code>name</code>, <code>lon</code>, <code>lat</code> in WGS84 degrees, and any key of
      the assessment file as a column, e.g. <code>tower.width</code>, <code>soil</code>) is assessed as <code>rocking inventory</code> assesses it:
      the assessment file with the row's cells set in it, the site's hazard from the grid at the tower's place. ζ<sub>E</sub> = a<sub>g,capacity</sub> / a<sub>g</sub>;
      a check fails when ζ<sub>E</sub> &lt; 1. Each tower's verdict is that of the worse of its ultimate limit states, each carried by the most
      refined method computed (non-linear dynamic, else non-linear kinematic, else linear kinematic; <code>assessment.verdict_method</code> may name another).</p>
      <div class="row">
        <label>Assessment file <select id="town-assess">${withGrid.map((a, i) => `<option value="${i}"${i === first ? " selected" : ""}>${esc(a.path)}</option>`).join("")}</select></label>
        or your own <input type="file" id="town-assess-file" accept=".toml,text/plain" aria-label="your own assessment file">
        with the hazard grid it names <input type="file" id="town-grid-file" aria-label="the hazard grid your assessment file names">
        <span id="town-assess-name"></span>
      </div>
      <div class="row">
        <label>Towers (CSV) <input type="file" id="town-towers-file" accept=".csv,text/csv,text/plain"></label>
        <button type="button" id="town-example">the example town</button>
        <span id="town-towers-name"></span>
      </div>
      <div class="row">
        <label>Records of the dynamic checks (3 or more: AT2, ESM, CSV) <input type="file" id="town-records-file" multiple></label>
        <button type="button" id="town-dynamic" disabled>Run the dynamic checks</button>
        <button type="button" id="town-cancel" disabled>Cancel</button>
        <progress id="town-progress" value="0" max="1" aria-label="towers assessed"></progress> <span id="town-progress-label" aria-live="polite"></span>
      </div>
      <div id="town-error" role="alert" hidden></div>
      <p id="town-summary" role="status"></p>
      <div class="row">Download: <button type="button" id="town-csv" disabled>inventory.csv</button>
        <button type="button" id="town-geojson" disabled>inventory.geojson</button></div>
      <div id="town-view">
        <canvas id="town-map" width="640" height="560" role="img" aria-label="Map of the towers (none assessed yet)"></canvas>
        <table id="town-ranking"><caption>The towers ranked by their governing ζ<sub>E</sub> (least first)</caption><thead></thead><tbody></tbody></table>
      </div>`;
    $("town-assess").addEventListener("change", () => {
      this.own = null;
      $("town-assess-name").textContent = "";
      this.run(false);
    });
    // The user's own file and its grid: the records it names are matched by file name to those picked.
    const picked = async (e) => {
      const file = e.target.files[0];
      return file ? { name: file.name, text: await file.text() } : null;
    };
    $("town-assess-file").addEventListener("change", async (e) => {
      this.own = (await picked(e)) ?? this.own;
      $("town-assess-name").textContent = this.own ? this.own.name : "";
      this.run(false);
    });
    $("town-grid-file").addEventListener("change", async (e) => {
      this.grid = (await picked(e)) ?? this.grid;
      if (this.own) this.run(false);
    });
    $("town-towers-file").addEventListener("change", async (e) => {
      const file = e.target.files[0];
      if (!file) return;
      this.towers = { name: file.name, text: await file.text() };
      this.run(false);
    });
    $("town-example").addEventListener("click", () => {
      const town = towns.find((t) => t.path === EXAMPLE_TOWN) || towns[0];
      this.towers = { name: town.path, text: town.csv };
      this.run(false);
    });
    $("town-records-file").addEventListener("change", async (e) => {
      this.records = await Promise.all([...e.target.files].map(async (f) => ({ name: f.name, text: await f.text() })));
      this.updateButtons();
    });
    $("town-dynamic").addEventListener("click", () => this.run(true));
    $("town-cancel").addEventListener("click", () => this.cancel());
    $("town-csv").addEventListener("click", () => download("inventory.csv", this.result.csv, "text/csv"));
    $("town-geojson").addEventListener("click", () => download("inventory.geojson", this.result.town.geojson, "application/geo+json"));
    this.updateButtons();
  }

  updateButtons(running = false) {
    $("town-dynamic").disabled = running || !this.towers || this.records.length === 0;
    $("town-cancel").disabled = !running;
    $("town-csv").disabled = !this.result;
    $("town-geojson").disabled = !this.result;
  }

  cancel() {
    this.worker?.terminate();
    this.worker = null;
    this.panel.dataset.state = this.result ? "done" : "idle";
    $("town-progress-label").textContent = "cancelled";
    this.updateButtons();
  }

  /** Assesses the towers chosen: the kinematic checks, or with `dynamic` the record set's too. */
  run(dynamic) {
    if (!this.towers) return;
    this.worker?.terminate();
    this.worker = new Worker(new URL("./town-worker.js", import.meta.url), { type: "module" });
    const id = ++this.id;
    const example = this.assessments[Number($("town-assess").value)];
    const entry = this.own
      ? { toml: this.own.text, path: this.own.name, grid: this.grid?.text ?? null, gridName: this.grid?.name ?? null }
      : { toml: example.toml, path: example.path, grid: grids[example.grid] ?? null, gridName: null };
    $("town-towers-name").textContent = this.towers.name;
    this.panel.dataset.state = "running";
    $("town-progress").value = 0;
    $("town-progress-label").textContent = dynamic ? "the dynamic checks…" : "";
    this.updateButtons(true);
    this.worker.onmessage = ({ data }) => {
      if (data.id !== this.id) return;
      if (data.progress !== undefined) {
        $("town-progress").max = data.total;
        $("town-progress").value = data.progress;
        $("town-progress-label").textContent = `${data.progress} of ${data.total} towers`;
        this.panel.dataset.progress = String(data.progress);
        return;
      }
      this.worker.terminate();
      this.worker = null;
      if (data.error !== undefined) {
        // The file itself is wrong (its header, the assessment file): nothing is assessed.
        this.result = null;
        this.panel.town = null;
        this.panel.csv = null;
        $("town-summary").textContent = "";
        $("town-progress-label").textContent = "";
        $("town-ranking").tBodies[0].innerHTML = "";
        $("town-map").getContext("2d").clearRect(0, 0, $("town-map").width, $("town-map").height);
        this.showError(data.error);
      } else {
        this.result = data.result;
        $("town-error").hidden = true;
        $("town-progress").max = 1;
        $("town-progress").value = 1;
        $("town-progress-label").textContent = `${data.result.town.towers.length} towers in ${sig(data.ms / 1000, 2)} s${dynamic ? " (with the dynamic checks)" : ""}`;
        this.draw();
        this.panel.town = data.result.town;
        this.panel.csv = data.result.csv;
      }
      this.panel.dataset.state = "done";
      this.updateButtons();
    };
    this.worker.postMessage({
      id,
      assess: entry.toml,
      origin: entry.path,
      grid: entry.grid,
      gridName: entry.gridName,
      towers: this.towers.text,
      towersName: this.towers.name,
      records: dynamic ? this.records : [],
    });
  }

  showError(message) {
    $("town-error").textContent = message;
    $("town-error").hidden = false;
  }

  draw() {
    const { town } = this.result;
    const assessed = town.ranking.length;
    const failing = town.ranking.filter((i) => town.towers[i].zeta_E < 1).length;
    const bad = town.towers.filter((t) => t.zeta_E === null);
    $("town-summary").textContent =
      `${town.towers.length} towers: ${assessed} assessed, ${failing} of them failing (verdict ζ_E < 1), ${bad.length} not assessed.`;
    if (bad.length > 0) this.showError(bad.map((t) => t.error).join("\n"));
    drawMap($("town-map"), town, `${town.towers.length} towers of ${this.towers.name}`);
    const head = `<tr><th>rank</th><th>id</th><th>name</th><th>ζ<sub>E</sub></th><th>governing check</th></tr>`;
    $("town-ranking").tHead.innerHTML = head;
    $("town-ranking").tBodies[0].innerHTML = town.ranking
      .map((i, k) => {
        const t = town.towers[i];
        const fails = t.zeta_E < 1;
        return `<tr data-id="${esc(t.id)}"><td class="num">${k + 1}</td><td>${esc(t.id)}</td><td>${esc(t.name)}</td>` +
          `<td class="num${fails ? " fails" : ""}">${sig(t.zeta_E, 3)}${fails ? " (fails)" : ""}</td><td>${esc(t.governing.replace("_", " ").replace("_", " "))}</td></tr>`;
      })
      .join("");
  }
}

/** Draws the towers at their lon, lat (a degree of longitude as long as on the ground), coloured by ζ_E, with a colour bar. */
function drawMap(canvas, town, title) {
  const ctx = canvas.getContext("2d");
  const W = canvas.width;
  const H = canvas.height;
  ctx.clearRect(0, 0, W, H);
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, W, H);
  const placed = town.towers.filter((t) => t.lon !== null && t.lat !== null);
  const zetas = town.towers.map((t) => t.zeta_E).filter((z) => z !== null && Number.isFinite(z));
  const top = Math.min(TOP_BOUNDS[1], Math.max(TOP_BOUNDS[0], ...zetas));
  const [left, right, up, bottom] = [70, 120, 50, 50];
  ctx.fillStyle = "#000";
  ctx.font = "bold 15px sans-serif";
  ctx.textAlign = "center";
  ctx.fillText(title, W / 2, 20);
  ctx.font = "12px sans-serif";
  ctx.fillText("colour: the governing ζ_E = ag capacity / ag (below 1 a check fails)", W / 2, 38);
  if (placed.length === 0) return;
  const lons = placed.map((t) => t.lon);
  const lats = placed.map((t) => t.lat);
  let [x0, x1, y0, y1] = [Math.min(...lons), Math.max(...lons), Math.min(...lats), Math.max(...lats)];
  const k = Math.cos((((y0 + y1) / 2) * Math.PI) / 180); // ground length of a degree of longitude over one of latitude
  const pw = W - left - right;
  const ph = H - up - bottom;
  // Equal scales on the ground, the data's box padded by 8% and centred.
  const spanX = Math.max((x1 - x0) * k, 1e-4) * 1.16;
  const spanY = Math.max(y1 - y0, 1e-4) * 1.16;
  const scale = Math.min(pw / spanX, ph / spanY);
  const cx = (x0 + x1) / 2;
  const cy = (y0 + y1) / 2;
  const px = (lon) => left + pw / 2 + (lon - cx) * k * scale;
  const py = (lat) => up + ph / 2 - (lat - cy) * scale;
  [x0, x1] = [cx - pw / 2 / (k * scale), cx + pw / 2 / (k * scale)];
  [y0, y1] = [cy - ph / 2 / scale, cy + ph / 2 / scale];
  ctx.strokeStyle = "#888";
  ctx.strokeRect(left, up, pw, ph);
  // Ticks: 5 or so per axis, at round degrees.
  const ticks = (a, b) => {
    const raw = (b - a) / 5;
    const step = [1, 2, 5, 10].map((m) => m * 10 ** Math.floor(Math.log10(raw))).find((s) => s >= raw);
    const out = [];
    for (let v = Math.ceil(a / step) * step; v <= b; v += step) out.push(+v.toFixed(10));
    return out;
  };
  ctx.fillStyle = "#000";
  ctx.textAlign = "center";
  for (const v of ticks(x0, x1)) {
    ctx.fillText(String(+v.toFixed(4)), px(v), up + ph + 16);
    ctx.fillRect(px(v), up + ph, 1, 5);
  }
  ctx.fillText("longitude (° east, WGS84)", left + pw / 2, H - 10);
  ctx.textAlign = "right";
  for (const v of ticks(y0, y1)) {
    ctx.fillText(String(+v.toFixed(4)), left - 8, py(v) + 4);
    ctx.fillRect(left - 5, py(v), 5, 1);
  }
  ctx.save();
  ctx.translate(16, up + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center";
  ctx.fillText("latitude (° north, WGS84)", 0, 0);
  ctx.restore();
  // The towers: not assessed in grey, the others by ζ_E; the weakest named.
  const named = new Set(town.ranking.slice(0, NAMED_ON_MAP));
  ctx.textAlign = "left";
  for (const t of placed) {
    ctx.beginPath();
    ctx.arc(px(t.lon), py(t.lat), 7, 0, 2 * Math.PI);
    ctx.fillStyle = t.zeta_E === null ? "rgb(170,170,170)" : colour(t.zeta_E / top);
    ctx.fill();
    ctx.strokeStyle = "#000";
    ctx.stroke();
    if (named.has(t.index)) {
      ctx.fillStyle = "#000";
      ctx.fillText(t.id, px(t.lon) + 9, py(t.lat) - 6);
    }
  }
  // The colour bar, 0 to top, with the line ζ_E = 1.
  const bx = W - right + 30;
  for (let i = 0; i < ph; i++) {
    ctx.fillStyle = colour(1 - i / ph);
    ctx.fillRect(bx, up + i, 20, 1);
  }
  ctx.strokeStyle = "#000";
  ctx.strokeRect(bx, up, 20, ph);
  ctx.fillStyle = "#000";
  ctx.textAlign = "left";
  for (const v of ticks(0, top)) {
    const y = up + ph - (v / top) * ph;
    ctx.fillText(String(+v.toFixed(2)), bx + 26, y + 4);
    ctx.fillRect(bx + 20, y, 4, 1);
  }
  const one = up + ph - (1 / top) * ph;
  ctx.fillStyle = "#c00";
  ctx.fillRect(bx - 4, one - 1, 28, 2);
  ctx.save();
  ctx.translate(W - 12, up + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center";
  ctx.fillStyle = "#000";
  ctx.fillText("governing ζ_E (–)", 0, 0);
  ctx.restore();
  canvas.dataset.colourTop = String(top);
  canvas.setAttribute(
    "aria-label",
    `Map of ${placed.length} towers by longitude and latitude, coloured by the governing ζ_E from 0 to ${sig(top, 3)}; ` +
      `least: ${town.ranking.slice(0, 3).map((i) => `${town.towers[i].id} ${sig(town.towers[i].zeta_E, 3)}`).join(", ")}`,
  );
}

function download(name, text, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
