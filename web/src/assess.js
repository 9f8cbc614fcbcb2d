// The assess tab: the tower and the building of the page's form assessed to
// the code as `rocking assess` assesses them (Circolare 2019 §C8.7.1.2.1 with
// the NTC 2018 spectra, or EN 1998-1): the user gives the site (the code, the
// soil, the topography, each limit state's ag, F0, Tc*, or a hazard grid's
// site) and the assessment's parameters (FC, q, the capacity curve); the
// engine (crates/rocking-assess, in a Web Worker) gives the capacity and the
// kinematic checks, each with its capacity ag and ζ_E, and the governing one:
// the numbers of the command's assessment.json, bit for bit. With blocks on
// the tower (a belfry on its shaft) each block, with those above it, is a
// mechanism of its own: its capacity, its checks, and the governing check
// taken over every mechanism, as the command's `mechanisms`. The non-linear
// dynamic checks run on demand in a Web Worker of their own, with a progress
// bar, on the record files the user picks (given to the engine as text with
// their names, read by the command's reader): the command's numbers too.
// The fields come from the keys' description (the engine's `keys()`), each
// check's name and formula and the capacity's quantities from the engine
// (`checkTexts`, `capacityQuantities`, as report.html has them).
import uPlot from "../vendor/uPlot.esm.js";
import { sig } from "./spectrum.js";
import { yAxis } from "./charts.js";
import { assessments, grids } from "../examples.js";

const $ = (id) => document.getElementById(id);

/** The limit states of each code: damage (activation), life safety, collapse. */
const STATES = { ntc2018: ["SLD", "SLV", "SLC"], ec8: ["DL", "SD", "NC"] };
/** The keys of a limit state's table in each code (EC8 gives ag alone). */
const STATE_KEYS = { ntc2018: ["ag", "F0", "Tc_star"], ec8: ["ag"] };
/** The keys of [assessment] on the form, those of the dynamic checks after the first four. */
const ASSESSMENT_FIELDS = ["confidence_factor", "q", "capacity"];
const DYNAMIC_FIELDS = ["free_after", "units", "dt"];

/**
 * A field of assessment.json's sites as a column's heading: the name without
 * the outputs' unit suffix, the unit in parentheses (`Tc_star_s` → `Tc_star (s)`).
 */
function fieldHeading(name) {
  const m = /^(.*)_(g|s|m)$/.exec(name);
  return m ? `${m[1]} (${m[2]})` : name;
}

/**
 * The dotted key an error line names (`assess.toml: site.SLV.ag: must be …`
 * → `site.SLV.ag`; a block's by its place, `block[1].name`), or "". The
 * page's form reads its errors with it too.
 */
export function keyOf(message) {
  const m = /^(?:[^:]*\.toml: )?([A-Za-z_][\w.]*(?:\[\d+\][\w.]*)*): /.exec(message);
  return m ? m[1] : "";
}

/** A field's text as a value: a number if it reads as one, else the text (the engine names the key and the type). */
function parseValue(text) {
  const s = text.trim();
  if (s === "") return undefined;
  const x = Number(s);
  return Number.isFinite(x) ? x : s;
}

/** A text field (its name the dotted key) with its label and unit. */
function textField(name, label, unit, placeholder = "") {
  return `<label class="field"><span>${label}</span><input type="text" inputmode="decimal" name="${name}" id="assess-${name}" placeholder="${placeholder}"><span class="unit">${unit}</span></label>`;
}

function selectField(name, label, options, title = "") {
  const opts = options.map(([v, t]) => `<option value="${v}">${t}</option>`).join("");
  return `<label class="field"${title ? ` title="${escapeHtml(title)}"` : ""}><span>${label}</span><select name="${name}" id="assess-${name}">${opts}</select><span class="unit"></span></label>`;
}

function escapeHtml(text) {
  return String(text).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
}

/**
 * The field of a key of the keys' description (`doc`, as `rocking keys --json`
 * gives it), named `name` (the dotted key; a limit state's in place of `<LS>`):
 * a choice of its values (an absent first one if it has a placeholder), or a
 * text field with its unit (or its symbol) and the default as placeholder;
 * its meaning as the title.
 */
function keyField(doc, name = doc.key) {
  const label = name.split(".").pop();
  if (doc.choices.length) {
    const options = doc.choices.map((c) => [c, c]);
    if (doc.placeholder) options.unshift(["", `(${doc.placeholder})`]);
    return selectField(name, label, options, doc.meaning);
  }
  const unit = doc.unit || (doc.symbol && doc.symbol !== label ? doc.symbol : "");
  return textField(name, label, unit, doc.placeholder).replace('<label class="field">', `<label class="field" title="${escapeHtml(doc.meaning)}">`);
}

/** Runs the engine's calls in a Web Worker; a newer call of a kind makes the older one's answer moot. */
class Engine {
  constructor() {
    this.worker = null;
    this.id = 0;
    this.waiting = new Map();
  }

  call(message) {
    if (!this.worker) {
      this.worker = new Worker(new URL("./assess-worker.js", import.meta.url), { type: "module" });
      this.worker.onmessage = ({ data }) => {
        const job = this.waiting.get(data.id);
        this.waiting.delete(data.id);
        if (!job) return;
        if (data.error !== undefined) job.reject(new Error(data.error));
        else job.resolve({ ...data.result, ms: data.ms });
      };
    }
    const id = ++this.id;
    return new Promise((resolve, reject) => {
      this.waiting.set(id, { resolve, reject });
      this.worker.postMessage({ id, ...message });
    });
  }
}

export class AssessView {
  /**
   * `panel`: the tab's section; `page`: { scenario() (the page's scenario
   * object), apply(sections) (puts an assessment file's tower, building,
   * name… into the page's scenario and recomputes) }.
   */
  constructor(panel, page) {
    this.panel = panel;
    this.page = page;
    this.engine = new Engine();
    this.requested = 0;
    this.visible = false;
    this.dirty = true;
    this.result = null;
    this.gridText = null; // the text of the hazard grid chosen, and its name
    this.gridName = "";
    this.started = false; // whether the tab has been shown (its worker started)
    this.records = []; // the record set picked: [{ name, text }]
    this.dynamic = null; // the dynamic checks' result, the worker running them, the table they ran on
    this.dynamicWorker = null;
    this.texts = {}; // each check's name and formula (HTML), from the engine
    this.chartMechanism = ""; // the mechanism the ADRS chart shows ("": the governing one)
    this.ready = window.rocking.keys().then((keys) => this.build(keys.assessment));
  }

  build(described) {
    const doc = new Map(described.map((k) => [k.key, k]));
    const field = (key, name = key) => keyField(doc.get(key), name);
    const states = (code) =>
      STATES[code]
        .map(
          (st) =>
            `<fieldset class="state" data-code="${code}"><legend>[site.${st}]</legend>` +
            STATE_KEYS[code].map((k) => field(`site.<LS>.${k}`, `site.${st}.${k}`)).join("") +
            `</fieldset>`,
        )
        .join("");
    this.panel.innerHTML = `
      <h2>Assessment to the code</h2>
      <p class="note">The tower and the building of the form, assessed as <code>rocking assess</code> does (Circolare 2019 §C8.7.1.2.1):
      its capacity as one rigid block and the kinematic checks, each with the least ground acceleration at which it stops holding
      and ζ_E = a<sub>g,capacity</sub> / a<sub>g</sub>; and, on the record files you pick, the non-linear dynamic checks (below the form).
      With blocks on the tower, each block with those above it is a mechanism of its own, turning on the block below; its kinematic
      checks take the ground's spectra for the motion of the top of the block below (which moves with the ground while the tower stands).</p>
      <div class="row"><label>Example <select id="assess-example"><option value="">—</option></select></label></div>
      <div id="assess-error" role="alert" hidden></div>
      <div id="assess-results">
        <p id="assess-governing" role="status"></p>
        <div class="scroll" role="region" aria-label="the checks" tabindex="0">
          <table id="assess-checks"><caption>Checks (those of rocking assess)</caption>
            <thead><tr><th>limit state</th><th>check</th><th>ag (g)</th><th>ag capacity (g)</th><th>ζ_E</th><th>verdict</th><th>demand</th><th>capacity</th><th>formula</th></tr></thead>
            <tbody></tbody></table>
        </div>
        <div class="tables">
          <div class="scroll" role="region" aria-label="the capacity" tabindex="0">
            <table id="assess-capacity"><caption>Capacity of the tower</caption><thead></thead><tbody></tbody></table>
          </div>
          <div class="scroll" role="region" aria-label="the site's spectra" tabindex="0">
            <table id="assess-sites"><caption>The site's spectra (5%)</caption><thead></thead><tbody></tbody></table>
          </div>
        </div>
        <div class="row downloads">Download: <button type="button" id="assess-download">assessment.json</button>
          <button type="button" id="assess-download-csv">capacity.csv</button> <span id="assess-time"></span></div>
        <div class="row" id="assess-adrs-pick" hidden><label>Mechanism in the chart <select id="assess-adrs-mechanism"></select></label></div>
        <div id="assess-adrs" class="chart" role="img" aria-label="the capacity curve in the ADRS plane with the ultimate displacements and the demands"></div>
      </div>
      <form id="assess-form" autocomplete="off">
        <fieldset><legend>[site]</legend>
          ${field("site.code")}${field("site.soil")}
          <div data-code="ntc2018">${field("site.topography")}</div>
          <div data-code="ec8">${field("site.spectrum_type")}</div>
        </fieldset>
        ${states("ntc2018")}${states("ec8")}
        <details id="assess-grid-box" data-code="ntc2018"><summary>SLD, SLV, SLC from a hazard grid</summary>
          <div class="row"><label>grid <select id="assess-grid"></select></label>
            <button type="button" id="assess-grid-button">a grid file…</button>
            <input type="file" id="assess-grid-file" hidden aria-label="a hazard grid file (NTC Allegato B layout)"></div>
          ${field("site.lon")}${field("site.lat")}${field("site.VN")}${field("site.CU")}
          <div class="row"><button type="button" id="assess-grid-fill">Fill SLD, SLV, SLC</button></div>
          <p id="assess-grid-note" class="note" aria-live="polite"></p>
        </details>
        <fieldset><legend>[assessment]</legend>
          ${ASSESSMENT_FIELDS.map((k) => field(`assessment.${k}`)).join("")}
        </fieldset>
      </form>
      <p id="assess-note" class="note"></p>
      <section id="assess-dynamic" aria-labelledby="assess-dynamic-title">
        <h3 id="assess-dynamic-title">Non-linear dynamic checks</h3>
        <p class="note">The record set fitted to each limit state's spectrum and every record run through the model (the tower, and the building
        sliding if the form has one), λ scanned and bisected, as <code>rocking assess</code> does (§C8.7.1.2.1.9). Pick 3 record files or more
        (AT2, ESM or CSV; 7 or more for the mean response). They stay in this page: nothing is sent anywhere.</p>
        <div class="row"><button type="button" id="assess-records-button">Record files…</button>
          <input type="file" id="assess-records-file" multiple hidden aria-label="the record files of the set">
          <span id="assess-records-list" aria-live="polite">no records picked</span></div>
        <form id="assess-dynamic-form" autocomplete="off">
          <fieldset><legend>[assessment]</legend>
            ${DYNAMIC_FIELDS.map((k) => field(`assessment.${k}`)).join("")}
            ${textField("assessment.lambda.from", "λ from", "", "0.05")}${textField("assessment.lambda.to", "λ to", "", "3")}${textField("assessment.lambda.step", "λ step", "", "0.05")}
            ${textField("assessment.period_range.0", "fit from", "s", "0.15")}${textField("assessment.period_range.1", "fit to", "s", "max(2, T_SLC)")}
          </fieldset>
        </form>
        <div class="row"><button type="button" id="assess-dynamic-run">Run the dynamic checks</button>
          <button type="button" id="assess-dynamic-cancel" hidden>Cancel</button>
          <progress id="assess-dynamic-progress" value="0" max="1" aria-label="progress of the dynamic checks" hidden></progress>
          <span id="assess-dynamic-label" role="status"></span></div>
        <div id="assess-dynamic-results" hidden>
          <p id="assess-records-note" class="note" hidden>Each mechanism reads the same runs: the table gives its largest d* (its own block's
          rotation on the block below), or <b class="fails">fell</b> where the record made it collapse (its block or one under it overturned).</p>
          <div class="scroll" role="region" aria-label="the records' responses" tabindex="0">
            <table id="assess-records"><caption>Each record at its fitted scale (λ = 1)</caption>
              <thead></thead>
              <tbody></tbody></table>
          </div>
          <div class="row downloads">Download: <button type="button" id="assess-download-dynamic">assessment.json</button>
            <button type="button" id="assess-download-records">records.csv</button> <button type="button" id="assess-download-spectra">spectra.csv</button></div>
        </div>
      </section>`;
    const example = $("assess-example");
    assessments.forEach((e, i) => example.append(new Option(e.path, String(i))));
    example.addEventListener("change", () => {
      const e = assessments[Number(example.value)];
      if (e) this.loadExample(e);
    });
    const grid = $("assess-grid");
    for (const path of Object.keys(grids)) grid.append(new Option(path, path));
    grid.append(new Option("(the file chosen)", ""));
    grid.addEventListener("change", () => {
      if (grid.value) this.setGrid(grids[grid.value], grid.value);
    });
    if (grid.options.length > 1) this.setGrid(grids[grid.options[0].value], grid.options[0].value);
    $("assess-grid-button").addEventListener("click", () => $("assess-grid-file").click());
    $("assess-grid-file").addEventListener("change", async (ev) => {
      const file = ev.target.files[0];
      if (!file) return;
      this.setGrid(await file.text(), file.name);
      grid.value = "";
    });
    $("assess-grid-fill").addEventListener("click", () => this.fillFromGrid());
    const form = $("assess-form");
    form.addEventListener("input", (ev) => {
      if (ev.target.name?.startsWith("site.") && ["lon", "lat", "VN", "CU"].includes(ev.target.name.slice(5))) return;
      // A limit state's value typed by hand: SLD, SLV, SLC are no longer the grid's.
      if (/^site\.SL[DVC]\./.test(ev.target.name ?? "")) $("assess-grid-note").textContent = "";
      this.changed();
    });
    form.addEventListener("change", (ev) => {
      if (ev.target.name === "site.code") this.showCode();
    });
    $("assess-download").addEventListener("click", () => this.download("assessment.json"));
    $("assess-download-csv").addEventListener("click", () => this.download("capacity.csv"));
    $("assess-records-button").addEventListener("click", () => $("assess-records-file").click());
    $("assess-records-file").addEventListener("change", async (ev) => {
      const files = [...ev.target.files];
      if (!files.length) return;
      this.setRecords(await Promise.all(files.map(async (f) => ({ name: f.name, text: await f.text() }))));
    });
    $("assess-dynamic-form").addEventListener("input", () => this.dynamicChanged());
    $("assess-dynamic-run").addEventListener("click", () => this.runDynamic());
    $("assess-dynamic-cancel").addEventListener("click", () => this.stopDynamic("Cancelled."));
    $("assess-download-dynamic").addEventListener("click", () => this.downloadDynamic("assessment.json"));
    $("assess-download-records").addEventListener("click", () => this.downloadDynamic("records.csv"));
    $("assess-download-spectra").addEventListener("click", () => this.downloadDynamic("spectra.csv"));
    $("assess-adrs-mechanism").addEventListener("change", (ev) => {
      this.chartMechanism = ev.target.value;
      this.drawChart();
    });
    new ResizeObserver(() => this.resizeChart()).observe($("assess-adrs"));
    this.showCode();
  }

  /** The record set picked: [{ name, text }], in the order given. */
  setRecords(records) {
    this.records = records;
    $("assess-records-list").textContent = records.length
      ? `${records.length} record${records.length === 1 ? "" : "s"}: ${records.map((r) => r.name).join(", ")}`
      : "no records picked";
    this.dynamicChanged();
  }

  /** Shows the fields of the chosen code only (the others keep their values). */
  showCode() {
    const code = this.field("site.code").value;
    for (const el of this.panel.querySelectorAll("[data-code]")) el.hidden = el.dataset.code !== code;
  }

  field(name) {
    return this.panel.querySelector(`[name="${CSS.escape(name)}"]`);
  }

  setGrid(text, name) {
    this.gridText = text;
    this.gridName = name;
  }

  /** Puts a value in a field (undefined empties it). */
  set(name, value) {
    const el = this.field(name);
    if (el) el.value = value === undefined || value === null ? (el.tagName === "SELECT" ? el.options[0].value : "") : String(value);
  }

  /**
   * Loads an assessment file of the examples: its site and parameters into
   * the tab and, unless `tower` is false, its tower, building and name into
   * the page's form. A grid's site fills SLD, SLV, SLC with the grid's values.
   */
  async loadExample(example, { tower = true } = {}) {
    let table;
    try {
      table = window.rocking.fromToml(example.toml);
    } catch (e) {
      return this.showError(`${example.path}: ${e.message.replace(/^scenario\.toml: /, "")}`);
    }
    // [support] (an elastic support under the tower: the checks at height) is the command's alone.
    const { site = {}, assessment = {}, support, ...sections } = table;
    this.set("site.code", site.code || "ntc2018");
    this.set("site.soil", site.soil);
    this.set("site.topography", site.topography || "T1");
    this.set("site.spectrum_type", site.spectrum_type ?? 1);
    for (const code of Object.keys(STATES)) for (const st of STATES[code]) for (const k of STATE_KEYS[code]) this.set(`site.${st}.${k}`, site[st]?.[k]);
    for (const k of ["lon", "lat", "VN", "CU"]) this.set(`site.${k}`, site[k]);
    for (const k of [...ASSESSMENT_FIELDS, ...DYNAMIC_FIELDS]) this.set(`assessment.${k}`, assessment[k]);
    for (const k of ["from", "to", "step"]) this.set(`assessment.lambda.${k}`, assessment.lambda?.[k]);
    for (const i of [0, 1]) this.set(`assessment.period_range.${i}`, assessment.period_range?.[i]);
    this.showCode();
    const records = Array.isArray(assessment.records) ? assessment.records : [];
    $("assess-note").textContent = records.length && tower
      ? `${example.path} names its record set for the non-linear dynamic checks: ${records.join(", ")} (relative to the file). ` +
        "Pick those files below to run them here, or run rocking assess " + example.path + "."
      : "";
    if (support) {
      $("assess-note").textContent +=
        ` ${example.path} stands the tower on an elastic support ([support]): its checks at height are rocking assess's; this tab checks the tower at ground level on a rigid support.`;
    }
    if (tower && sections.tower) this.page.apply(sections);
    if (site.grid) {
      // The grid's path from the root, resolved when the examples were bundled.
      const path = example.grid;
      if (grids[path] !== undefined) {
        this.setGrid(grids[path], path);
        $("assess-grid").value = path;
      }
      $("assess-grid-box").open = true;
      await this.fillFromGrid();
    } else this.changed();
  }

  /** Fills SLD, SLV, SLC with the grid's values at lon, lat for VN, CU (rocking assess's, bit for bit). */
  async fillFromGrid() {
    const read = (k, fallback) => {
      const v = parseValue(this.field(`site.${k}`).value);
      return v === undefined ? fallback : v;
    };
    const [lon, lat, VN, CU] = [read("lon", NaN), read("lat", NaN), read("VN", 50), read("CU", 1)];
    for (const [k, v] of Object.entries({ lon, lat, VN, CU })) {
      if (typeof v !== "number" || !Number.isFinite(v)) return this.showError(`site.${k}: ${Number.isNaN(v) ? "required with a grid" : `must be a number, got ${JSON.stringify(v)}`}`);
    }
    if (!this.gridText) return this.showError("site.grid: choose a hazard grid file");
    try {
      const values = await this.engine.call({ kind: "grid", grid: this.gridText, lon, lat, VN, CU });
      for (const st of STATES.ntc2018) for (const k of STATE_KEYS.ntc2018) this.set(`site.${st}.${k}`, values[st][k]);
      $("assess-grid-note").textContent =
        `SLD, SLV, SLC from ${this.gridName} at lon ${lon}, lat ${lat}, VN ${VN}, CU ${CU}` +
        (/synthetic/i.test(this.gridName) ? " (a SYNTHETIC grid: illustrative values only; give the official one for a real site)." : ".");
      this.changed();
    } catch (e) {
      this.showError(e.message);
    }
  }

  /** The assessment file's table: the page's scenario without its ground, plus [site] and [assessment]. */
  table() {
    const s = structuredClone(this.page.scenario());
    delete s.ground;
    if (s.simulation) {
      // An assessment runs no simulation of its own length.
      delete s.simulation.duration;
      if (!Object.keys(s.simulation).length) delete s.simulation;
    }
    const code = this.field("site.code").value;
    const site = { code, soil: this.field("site.soil").value };
    if (code === "ntc2018") site.topography = this.field("site.topography").value;
    else site.spectrum_type = Number(this.field("site.spectrum_type").value);
    for (const st of STATES[code]) {
      const t = {};
      for (const k of STATE_KEYS[code]) {
        const v = parseValue(this.field(`site.${st}.${k}`).value);
        if (v !== undefined) t[k] = v;
      }
      if (Object.keys(t).length) site[st] = t;
    }
    const assessment = {};
    for (const k of ASSESSMENT_FIELDS) {
      const v = parseValue(this.field(`assessment.${k}`).value);
      if (v !== undefined) assessment[k] = v;
    }
    return { ...s, site, assessment };
  }

  /** The table of the dynamic checks: the assessment's, with the record set picked and the dynamic checks' keys. */
  dynamicTable() {
    const table = this.table();
    const a = table.assessment;
    for (const k of DYNAMIC_FIELDS) {
      const v = parseValue(this.field(`assessment.${k}`).value);
      if (v !== undefined) a[k] = v;
    }
    const lambda = {};
    for (const k of ["from", "to", "step"]) {
      const v = parseValue(this.field(`assessment.lambda.${k}`).value);
      if (v !== undefined) lambda[k] = v;
    }
    if (Object.keys(lambda).length) a.lambda = lambda;
    const range = [0, 1].map((i) => parseValue(this.field(`assessment.period_range.${i}`).value));
    if (range.some((v) => v !== undefined)) a.period_range = range.map((v) => v ?? null);
    a.records = this.records;
    return table;
  }

  /** The page's scenario changed (the tower, the building…): recompute when shown. */
  scenarioChanged() {
    this.changed();
  }

  /** The tab shown or hidden. */
  async show(visible) {
    await this.ready;
    this.visible = visible;
    if (visible && !this.started) {
      this.started = true;
      // The first time: the first example's site (not its tower: the form's stays).
      if (assessments[0]) return this.loadExample(assessments[0], { tower: false });
    }
    if (visible && this.dirty) this.compute();
  }

  changed() {
    this.dynamicChanged();
    this.dirty = true;
    this.panel.classList.add("stale");
    if (this.visible) this.compute();
  }

  async compute() {
    await this.ready;
    this.dirty = false;
    const id = ++this.requested;
    this.panel.dataset.state = "computing";
    const table = this.table();
    try {
      const { texts, quantities, ...result } = await this.engine.call({ kind: "assess", table: JSON.stringify(table) });
      if (id !== this.requested) return;
      this.texts = texts;
      this.quantities = quantities;
      this.result = result;
      // Kept on the element too, for the page's tests.
      this.panel.assessment = result;
      this.showError("");
      this.render();
      $("assess-time").textContent = `Computed in ${result.ms.toFixed(1)} ms.`;
      this.panel.classList.remove("stale");
      this.panel.dataset.state = "done";
    } catch (e) {
      if (id !== this.requested) return;
      this.showError(e.message);
      this.panel.dataset.state = "error";
    }
  }

  /** An error line in the tab's banner and beside the field it names (or clears them with ""). */
  showError(message) {
    const box = $("assess-error");
    box.textContent = message;
    box.hidden = !message;
    for (const el of this.panel.querySelectorAll("[aria-invalid]")) {
      el.removeAttribute("aria-invalid");
      el.removeAttribute("aria-describedby");
    }
    for (const el of this.panel.querySelectorAll(".field-error")) el.remove();
    if (!message) return;
    this.panel.classList.add("stale");
    const key = keyOf(message);
    // The field of the key, or the first of the table it names (`site.SLV`: missing).
    const input = key && (this.field(key) || [...this.panel.querySelectorAll("[name]")].find((el) => el.name.startsWith(`${key}.`) && !el.closest("[hidden]")));
    if (!input) return;
    if (input.closest("details")) input.closest("details").open = true;
    input.setAttribute("aria-invalid", "true");
    const note = document.createElement("div");
    note.className = "field-error";
    note.id = `assess-error-${key}`;
    note.textContent = message.slice(message.indexOf(key) + key.length + 2);
    input.closest(".field").after(note);
    input.setAttribute("aria-describedby", note.id);
  }

  /** A check's name and formula (HTML), as the engine writes them for report.html. */
  text(method) {
    return this.texts[method] || { name: method, formula_html: "" };
  }

  render() {
    const r = this.result;
    // The dynamic checks' result, when they ran on the assessment shown: the
    // same capacities and sites, every check.
    const shown = this.dynamic?.result ?? r;
    const mechanisms = mechanismsOf(shown);
    const stacked = mechanisms.length > 1;
    const governing = shown.governing;
    const governs = (m, c) =>
      !!governing && governing.limit_state === c.limit_state && governing.method === c.method && (governing.mechanism ?? "tower") === m.name;
    const cell = (value, digits, bound = false) => `<td class="num" data-value="${value}">${bound ? "≥ " : ""}${sig(value, digits)}</td>`;
    const unit = (u) => u.replace("m/s2", "m/s²");
    const row = (m, c) => {
      const t = this.text(c.method);
      const data = `data-mechanism="${escapeHtml(m.name)}" data-limit-state="${c.limit_state}" data-method="${c.method}"`;
      if (c.completed === false) {
        return `<tr ${data}><td>${c.limit_state}</td><td>${t.name}</td>` +
          `<td colspan="6" class="fails">could not be completed: ${escapeHtml(c.error || "a record failed")}</td><td class="formula">${t.formula_html}</td></tr>`;
      }
      const isGoverning = governs(m, c);
      const bound = c.ag_capacity_is_lower_bound;
      return (
        `<tr ${data}${isGoverning ? ' class="governing"' : ""}>` +
        `<td>${c.limit_state}</td><td>${t.name}${isGoverning ? " (governing)" : ""}</td>` +
        cell(c.ag_g, 4) +
        cell(c.ag_capacity_g, 4, bound) +
        cell(c.zeta_E, 3, bound) +
        `<td class="${c.holds ? "holds" : "fails"}">${c.holds ? "holds" : "fails"}</td>` +
        `<td class="num" data-value="${c.demand}">${sig(c.demand, 4)} ${unit(c.unit)}</td>` +
        `<td class="num" data-value="${c.capacity}">${sig(c.capacity, 4)} ${unit(c.unit)}</td>` +
        `<td class="formula">${t.formula_html}</td></tr>`
      );
    };
    // With blocks, each mechanism's checks under a row that says what turns on what.
    const body = mechanisms.flatMap((m, i) => [
      ...(stacked ? [`<tr class="mechanism" data-mechanism="${escapeHtml(m.name)}"><th colspan="9" scope="colgroup">${escapeHtml(describe(mechanisms, i))}</th></tr>`] : []),
      ...m.checks.map((c) => row(m, c)),
    ]);
    this.panel.querySelector("#assess-checks tbody").innerHTML = body.join("");
    const g = governing;
    const line = $("assess-governing");
    if (g) {
      const gm = this.text(g.method);
      const bound = g.ag_capacity_is_lower_bound ? "≥ " : "";
      const of = stacked ? ` of the ${escapeHtml(g.mechanism ?? "tower")}` : "";
      line.innerHTML =
        `Governing: ${g.limit_state} ${gm.name}${of} (${gm.formula_html}): ag capacity ${bound}${sig(g.ag_capacity_g, 4)} g ` +
        `against ag ${sig(g.ag_g, 4)} g, ζ_E = ${bound}${sig(g.zeta_E, 3)}: ${g.holds ? "it holds" : "it FAILS"}. ` +
        (g.verdict_basis === "named"
          ? "Its method carries the verdict as assessment.verdict_method names it; the other checks are information."
          : "The most refined method computed carries the verdict of SLV and SLC; the other checks are information, SLD's activation beside it.");
    } else line.textContent = "";
    line.classList.toggle("danger", !!g && !g.holds);
    // The capacity: a column per mechanism.
    const capacity = this.panel.querySelector("#assess-capacity");
    capacity.querySelector("caption").textContent = stacked ? "Capacity of each mechanism" : "Capacity of the tower";
    capacity.querySelector("thead").innerHTML = stacked
      ? `<tr><th scope="col">quantity</th>${mechanisms.map((m) => `<th scope="col">${escapeHtml(m.name)}</th>`).join("")}<th scope="col">unit</th></tr>`
      : "";
    capacity.querySelector("tbody").innerHTML =
      this.quantities
        .map(
          (q) =>
            `<tr><td class="label" title="${escapeHtml(q.meaning)}">${q.symbol_html}</td>` +
            mechanisms.map((m) => `<td class="num" data-mechanism="${escapeHtml(m.name)}" data-key="${q.key}" data-value="${m.capacity[q.key]}">${sig(m.capacity[q.key], 4)}</td>`).join("") +
            `<td>${q.unit}</td></tr>`,
        )
        .join("") + `<tr><td class="label">curve</td><td colspan="${mechanisms.length + 1}">${r.capacity.curve}</td></tr>`;
    // The sites' columns: every field assessment.json gives for a limit state, in its order.
    const states = Object.keys(r.sites);
    const fields = [...new Set(states.flatMap((s) => Object.keys(r.sites[s])))];
    this.panel.querySelector("#assess-sites thead").innerHTML = `<tr><th>limit state</th>${fields.map((k) => `<th>${fieldHeading(k)}</th>`).join("")}</tr>`;
    this.panel.querySelector("#assess-sites tbody").innerHTML = states
      .map((s) => `<tr><td>${s}</td>${fields.map((k) => (r.sites[s][k] === undefined ? "<td></td>" : cell(r.sites[s][k], 4))).join("")}</tr>`)
      .join("");
    // The chart's choice of mechanism, with blocks.
    const pick = $("assess-adrs-mechanism");
    const names = mechanisms.map((m) => m.name);
    if ([...pick.options].map((o) => o.value).join("\n") !== ["", ...names].join("\n")) {
      pick.replaceChildren(new Option("the governing one", ""), ...names.map((n) => new Option(n, n)));
    }
    if (!names.includes(this.chartMechanism)) this.chartMechanism = "";
    pick.value = this.chartMechanism;
    $("assess-adrs-pick").hidden = !stacked;
    this.drawChart();
  }

  /**
   * The capacity curve in the ADRS plane (a* against d*), as report.html
   * draws it: the ultimate displacements d_SLV and d_SLC on it, the
   * non-linear kinematic demands at the site's ag and, when they ran, the
   * dynamic checks' responses (the mean, or the largest, of the set at λ = 1),
   * each at a*(d) of the curve; a demand that fails drawn as a cross.
   */
  drawChart() {
    const r = this.result;
    const box = $("assess-adrs");
    if (!r) return;
    // The mechanism chosen, or the governing one (the tower's with none).
    const shown = this.dynamic?.result ?? r;
    const mechanisms = mechanismsOf(shown);
    const name = this.chartMechanism || shown.governing?.mechanism || "tower";
    const index = Math.max(0, mechanisms.findIndex((m) => m.name === name));
    const m = mechanisms[index];
    const c = m.capacity;
    const curve = (shown.curves ?? [shown.curve])[index];
    // a* at the chart's points as the engine gives them (the curve's own a*(d)).
    const exact = new Map((shown.adrs?.[index] ?? []).map(([d, a]) => [d, a]));
    const at = (d) => {
      if (exact.has(d)) return exact.get(d);
      // Elsewhere, a* on the curve at d (linear between its points; 0 beyond d0).
      if (d >= curve[curve.length - 1][0]) return curve[curve.length - 1][1];
      const i = Math.max(1, curve.findIndex(([x]) => x >= d));
      const [[x0, y0], [x1, y1]] = [curve[i - 1], curve[i]];
      return x1 === x0 ? y0 : y0 + ((y1 - y0) * (d - x0)) / (x1 - x0);
    };
    const points = [
      { label: `d_SLV = 0.4 d0 = ${sig(c.d_SLV_m, 3)} m`, d: c.d_SLV_m, color: "#2a7a2a", fails: false },
      { label: `d_SLC = 0.6 d0 = ${sig(c.d_SLC_m, 3)} m`, d: c.d_SLC_m, color: "#7a4a9a", fails: false },
    ];
    const checks = m.checks;
    const colors = { nonlinear_kinematic: ["#d07a10", "#b04a10"], nonlinear_dynamic: ["#1f77b4", "#0b3d91"] };
    for (const k of checks.filter((k) => k.method in colors && k.completed !== false)) {
      const i = k.limit_state === states(r)[1] ? 0 : 1;
      points.push({
        label: `${k.limit_state} ${this.text(k.method).name} demand ${sig(k.demand, 3)} m`,
        d: Math.min(k.demand, c.d0_m),
        color: colors[k.method][i],
        fails: !k.holds,
      });
    }
    // One x array: the curve's points and each marker's d, sorted; each series null where it has no point.
    const xs = [...new Set([...curve.map(([d]) => d), ...points.map((p) => p.d)])].sort((a, b) => a - b);
    const curveAt = new Map(curve.map(([d, a]) => [d, a]));
    const data = [xs, xs.map((x) => curveAt.get(x) ?? null), ...points.map((p) => xs.map((x) => (x === p.d ? at(p.d) : null)))];
    const series = [
      {},
      { label: "capacity a*(d*) (m/s²)", stroke: "#222", width: 3, spanGaps: true, points: { show: false } },
      ...points.map((p) => ({
        label: p.label + (p.fails ? " (fails)" : ""),
        stroke: p.color,
        width: 0,
        paths: () => null,
        points: { show: true, size: p.fails ? 13 : 10, width: 2, stroke: p.color, fill: p.fails ? "#fff" : p.color },
      })),
    ];
    if (this.chart) this.chart.destroy();
    box.replaceChildren();
    this.chart = new uPlot(
      {
        width: this.chartWidth(),
        height: 300,
        title: `Capacity curve in the ADRS plane${mechanisms.length > 1 ? `: ${m.name}` : ""} (${c.curve} curve, FC = ${c.confidence_factor}, e* = ${c.e_star})`,
        legend: { live: false },
        scales: { x: { time: false, range: (u, min, max) => [0, Math.max(max, c.d0_m)] }, y: { range: (u, min, max) => [0, max * 1.05] } },
        series,
        axes: [{ label: "spectral displacement d* (m)" }, yAxis("spectral acceleration a* (m/s²)")],
      },
      data,
      box,
    );
    box.dataset.mechanism = m.name;
    box.dataset.points = JSON.stringify(points.map((p) => ({ label: p.label, d: p.d, a: at(p.d), fails: p.fails })));
  }

  chartWidth() {
    return Math.max(280, Math.min(760, $("assess-adrs").clientWidth || 700));
  }

  resizeChart() {
    if (this.chart && this.chart.width !== this.chartWidth()) this.chart.setSize({ width: this.chartWidth(), height: this.chart.height });
  }

  /** The dynamic checks' inputs changed: a result shown is no longer theirs. */
  dynamicChanged() {
    if (this.dynamicWorker) this.stopDynamic("Stopped: the inputs changed.");
    if (this.dynamic) {
      this.dynamic = null;
      $("assess-dynamic-results").hidden = true;
      $("assess-dynamic-label").textContent = "The inputs changed: run the dynamic checks again.";
      if (this.result) this.render();
    }
  }

  stopDynamic(message) {
    this.dynamicWorker?.terminate();
    this.dynamicWorker = null;
    $("assess-dynamic-cancel").hidden = true;
    $("assess-dynamic-progress").hidden = true;
    $("assess-dynamic-run").disabled = false;
    $("assess-dynamic-label").textContent = message;
    $("assess-dynamic").dataset.state = "stopped";
  }

  /** Runs the dynamic checks in a Web Worker of their own (cancelled by ending it), the progress shown. */
  async runDynamic() {
    await this.ready;
    if (this.dynamicWorker) this.stopDynamic("");
    this.dynamic = null;
    $("assess-dynamic-results").hidden = true;
    const section = $("assess-dynamic");
    const label = $("assess-dynamic-label");
    const bar = $("assess-dynamic-progress");
    if (this.records.length === 0) {
      label.textContent = "Pick the record files first (3 or more).";
      section.dataset.state = "error";
      return;
    }
    const table = JSON.stringify(this.dynamicTable());
    const worker = new Worker(new URL("./assess-dynamic-worker.js", import.meta.url), { type: "module" });
    this.dynamicWorker = worker;
    section.dataset.state = "running";
    bar.hidden = false;
    bar.value = 0;
    bar.max = 1;
    $("assess-dynamic-cancel").hidden = false;
    $("assess-dynamic-run").disabled = true;
    label.textContent = `Reading ${this.records.length} records…`;
    worker.onmessage = ({ data }) => {
      if (worker !== this.dynamicWorker) return;
      if (data.progress !== undefined) {
        bar.max = data.most;
        bar.value = data.progress;
        label.textContent = `${data.progress} of at most ${data.most} runs of a record`;
        return;
      }
      this.stopDynamic("");
      if (data.error !== undefined) {
        this.showError(data.error);
        label.textContent = "";
        section.dataset.state = "error";
        return;
      }
      this.dynamic = { result: data.result, table };
      // Kept on the element too, for the page's tests.
      section.assessment = data.result;
      this.showError("");
      this.render();
      this.renderRecords();
      $("assess-dynamic-results").hidden = false;
      label.textContent = `Done: ${data.runs} runs of a record in ${(data.ms / 1000).toFixed(1)} s.`;
      section.dataset.state = "done";
    };
    worker.postMessage({ table });
  }

  /** The table of each record's response at its fitted scale (records.csv's rows). A tower alone
   * has its d* and whether it overturned; a stack, as the command's report.html, one d* column per
   * mechanism under a shared head and `fell` in the cell of a mechanism the record made collapse
   * (its block or one under it overturned), so that the five blocks a tower may carry stay narrow. */
  renderRecords() {
    const num = (x) => (x === null || x === undefined ? "—" : `<span data-value="${x}">${sig(x, 4)}</span>`);
    const rows = this.dynamic.result.responses;
    const blocks = rows.length ? rows[0].blocks.map((b) => b.name) : [];
    const th = (h, span = "") => `<th${span}>${escapeHtml(h)}</th>`;
    const both = ' rowspan="2"';
    let head;
    let responses;
    if (blocks.length) {
      head =
        `<tr>${th("limit state", both)}${th("record", both)}${th("scale", both)}${th("max d* (m)", ` colspan="${blocks.length + 1}"`)}` +
        `${th("max slip of the building (m)", both)}${th("error", both)}</tr><tr>${["tower", ...blocks].map((b) => th(b)).join("")}</tr>`;
      // A mechanism that collapsed has no d* of its own to give; a record that failed, none at all.
      const cell = (r, m) => (r.error ? "<td></td>" : m.overturned ? '<td class="num fails">fell</td>' : `<td class="num">${num(m.max_control_displacement_m)}</td>`);
      responses = (r) => [r, ...r.blocks].map((m) => cell(r, m)).join("");
    } else {
      head = `<tr>${["limit state", "record", "scale", "max d* (m)", "overturned", "max slip of the building (m)", "error"].map((h) => th(h)).join("")}</tr>`;
      responses = (r) => `<td class="num">${num(r.max_control_displacement_m)}</td><td>${r.error ? "" : r.overturned}</td>`;
    }
    $("assess-records-note").hidden = blocks.length === 0;
    $("assess-records").classList.toggle("stack", blocks.length > 0);
    this.panel.querySelector("#assess-records thead").innerHTML = head;
    this.panel.querySelector("#assess-records tbody").innerHTML = rows
      .map((r) =>
        `<tr><td>${r.limit_state}</td><td>${escapeHtml(r.record)}</td><td class="num">${num(r.scale)}</td>${responses(r)}` +
        `<td class="num">${num(r.max_building_slip_m)}</td><td>${escapeHtml(r.error ?? "")}</td></tr>`)
      .join("");
  }

  /** The dynamic checks' assessment.json, records.csv or spectra.csv. */
  downloadDynamic(name) {
    const r = this.dynamic?.result;
    if (!r) return;
    const { curve, curves, adrs, records_csv, spectra_csv, responses, ...json } = r;
    const text = { "records.csv": records_csv, "spectra.csv": spectra_csv }[name] ?? JSON.stringify(json, null, 2) + "\n";
    save(name, text);
  }

  /** assessment.json (the command's, without a record set) or capacity.csv. */
  download(name) {
    if (!this.result) return;
    const { curve, curves, adrs, ms, ...json } = this.result;
    const text = name === "capacity.csv" ? "d_star_m,a_star_m_s2\n" + curve.map(([d, a]) => `${d},${a}`).join("\n") + "\n" : JSON.stringify(json, null, 2) + "\n";
    save(name, text);
  }
}

/** Offers `text` as a file named `name`. */
function save(name, text) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** The limit states of an assessment in order: damage, life safety, collapse. */
function states(r) {
  return Object.keys(r.sites);
}

/**
 * The mechanisms of an assessment, the tower's first: its `mechanisms` (with
 * blocks on the tower), or the tower's alone.
 */
function mechanismsOf(r) {
  return r.mechanisms ?? [{ name: "tower", block: 0, capacity: r.capacity, checks: r.checks, governing: r.governing, dynamic: r.dynamic }];
}

/** What turns on what in mechanism `i` of `mechanisms`: the tower with the whole stack, or a block with those above it on the one below. */
function describe(mechanisms, i) {
  const above = mechanisms.slice(i + 1).map((m) => m.name);
  const carried = above.length ? ` carrying ${above.join(" and ")}` : "";
  if (i === 0) return `tower${carried}, turning on its springing level`;
  return `${mechanisms[i].name}${carried}, turning on the ${mechanisms[i - 1].name}`;
}
