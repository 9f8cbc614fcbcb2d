// The assess tab: the tower and the building of the page's form assessed to
// the code as `rocking assess` assesses them (Circolare 2019 §C8.7.1.2.1 with
// the NTC 2018 spectra, or EN 1998-1): the user gives the site (the code, the
// soil, the topography, each limit state's ag, F0, Tc*, or a hazard grid's
// site) and the assessment's parameters (FC, q, the capacity curve); the
// engine (crates/rocking-assess, in a Web Worker) gives the capacity and the
// kinematic checks, each with its capacity ag and ζ_E, and the governing one:
// the numbers of the command's assessment.json, bit for bit. The dynamic
// checks (a record set run through the model) are the command's.
import { sig } from "./spectrum.js";
import { assessments, grids } from "../examples.js";

const $ = (id) => document.getElementById(id);

/** The limit states of each code: damage (activation), life safety, collapse. */
const STATES = { ntc2018: ["SLD", "SLV", "SLC"], ec8: ["DL", "SD", "NC"] };
/** The keys of a limit state's table, with their units. */
const STATE_KEYS = { ntc2018: [["ag", "g"], ["F0", ""], ["Tc_star", "s"]], ec8: [["ag", "g"]] };

/**
 * Each check's name and formula, as the command's report.html writes them
 * (crates/rocking-cli/src/commands/assess_report.rs), in plain text.
 */
const METHODS = {
  activation: { name: "activation", formula: () => "a_g S(a_g) ≥ a0* activates (Circolare 2019 eq. C8.7.1.8)" },
  linear_kinematic: { name: "linear kinematic", formula: (q) => `a_g > q · a_g,capacity(activation), q = ${q} (§C8.7.1.2.1.7)` },
  nonlinear_kinematic: { name: "non-linear kinematic", formula: () => "max over T ≤ T_LS of S_De(T; ξ) > d_LS, ξ = 8% (SLV), 10% (SLC) (§C8.7.1.2.1.8)" },
  nonlinear_dynamic: { name: "non-linear dynamic", formula: () => "records run through the model: none beyond d0, mean (largest with fewer than 7) ≤ d_LS (§C8.7.1.2.1.9)" },
};

/** The capacity's fields of assessment.json: [key, symbol, unit, meaning]. */
const CAPACITY = [
  ["alpha0", "α0 = b/h", "", "activation multiplier (§C8.7.1.2.1.3)"],
  ["e_star", "e*", "", "fraction of the mass that takes part"],
  ["m_star_kg", "M*", "kg", "participating mass"],
  ["a0_star_m_s2", "a0*", "m/s²", "spectral acceleration of activation, α0 g / (e* FC)"],
  ["d0_m", "d0", "m", "displacement at which the tower overturns"],
  ["d_SLV_m", "d_SLV = 0.4 d0", "m", "ultimate displacement, life safety (§C8.7.1.2.1.6)"],
  ["d_SLC_m", "d_SLC = 0.6 d0", "m", "ultimate displacement, collapse"],
  ["T_SLV_s", "T_SLV", "s", "secant period at 0.4 d_SLV"],
  ["T_SLC_s", "T_SLC", "s", "secant period at 0.4 d_SLC"],
];

/** A site spectrum's fields of assessment.json: [key, label]. */
const SITE_FIELDS = [
  ["ag_g", "ag (g)"],
  ["F0", "F0"],
  ["Tc_star_s", "Tc* (s)"],
  ["S", "S = SS ST"],
  ["TB_s", "TB (s)"],
  ["TC_s", "TC (s)"],
  ["TD_s", "TD (s)"],
];

/** The dotted key an error line names (`assess.toml: site.SLV.ag: must be …` → `site.SLV.ag`), or "". */
function keyOf(message) {
  const m = /^(?:[^:]*\.toml: )?([A-Za-z_][\w.]*): /.exec(message);
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

function selectField(name, label, options) {
  const opts = options.map(([v, t]) => `<option value="${v}">${t}</option>`).join("");
  return `<label class="field"><span>${label}</span><select name="${name}" id="assess-${name}">${opts}</select><span class="unit"></span></label>`;
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
    this.build();
  }

  build() {
    const states = (code) =>
      STATES[code]
        .map(
          (st) =>
            `<fieldset class="state" data-code="${code}"><legend>[site.${st}]</legend>` +
            STATE_KEYS[code].map(([k, u]) => textField(`site.${st}.${k}`, k === "Tc_star" ? "Tc*" : k, u)).join("") +
            `</fieldset>`,
        )
        .join("");
    this.panel.innerHTML = `
      <h2>Assessment to the code</h2>
      <p class="note">The tower and the building of the form, assessed as <code>rocking assess</code> does (Circolare 2019 §C8.7.1.2.1):
      its capacity as one rigid block and the kinematic checks, each with the least ground acceleration at which it stops holding
      and ζ_E = a<sub>g,capacity</sub> / a<sub>g</sub>. The non-linear dynamic checks (records run through the model) are the command's.</p>
      <div class="row"><label>Example <select id="assess-example"><option value="">—</option></select></label></div>
      <div id="assess-error" role="alert" hidden></div>
      <div id="assess-results">
        <p id="assess-governing" role="status"></p>
        <div class="scroll" role="region" aria-label="the checks" tabindex="0">
          <table id="assess-checks"><caption>Checks (the kinematic checks of rocking assess)</caption>
            <thead><tr><th>limit state</th><th>check</th><th>ag (g)</th><th>ag capacity (g)</th><th>ζ_E</th><th>verdict</th><th>demand</th><th>capacity</th><th>formula</th></tr></thead>
            <tbody></tbody></table>
        </div>
        <div class="tables">
          <table id="assess-capacity"><caption>Capacity of the tower</caption><tbody></tbody></table>
          <div class="scroll" role="region" aria-label="the site's spectra" tabindex="0">
            <table id="assess-sites"><caption>The site's spectra (5%)</caption><thead></thead><tbody></tbody></table>
          </div>
        </div>
        <div class="row downloads">Download: <button type="button" id="assess-download">assessment.json</button>
          <button type="button" id="assess-download-csv">capacity.csv</button> <span id="assess-time"></span></div>
      </div>
      <form id="assess-form" autocomplete="off">
        <fieldset><legend>[site]</legend>
          ${selectField("site.code", "code", [["ntc2018", "ntc2018 (NTC 2018)"], ["ec8", "ec8 (EN 1998-1)"]])}
          ${selectField("site.soil", "soil", ["A", "B", "C", "D", "E"].map((s) => [s, s]))}
          <div data-code="ntc2018">${selectField("site.topography", "topography", ["T1", "T2", "T3", "T4"].map((t) => [t, t]))}</div>
          <div data-code="ec8">${selectField("site.spectrum_type", "spectrum_type", [["1", "1"], ["2", "2"]])}</div>
        </fieldset>
        ${states("ntc2018")}${states("ec8")}
        <details id="assess-grid-box" data-code="ntc2018"><summary>SLD, SLV, SLC from a hazard grid</summary>
          <div class="row"><label>grid <select id="assess-grid"></select></label>
            <button type="button" id="assess-grid-button">a grid file…</button>
            <input type="file" id="assess-grid-file" hidden aria-label="a hazard grid file (NTC Allegato B layout)"></div>
          ${textField("site.lon", "lon", "° E")}${textField("site.lat", "lat", "° N")}
          ${textField("site.VN", "VN", "years", "50")}${textField("site.CU", "CU", "", "1")}
          <div class="row"><button type="button" id="assess-grid-fill">Fill SLD, SLV, SLC</button></div>
          <p id="assess-grid-note" class="note" aria-live="polite"></p>
        </details>
        <fieldset><legend>[assessment]</legend>
          ${textField("assessment.confidence_factor", "confidence_factor", "FC", "1.35")}
          ${textField("assessment.q", "q", "", "2")}
          ${selectField("assessment.capacity", "capacity", [["linear", "linear"], ["exact", "exact"]])}
        </fieldset>
      </form>
      <p id="assess-note" class="note"></p>`;
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
      this.changed();
    });
    form.addEventListener("change", (ev) => {
      if (ev.target.name === "site.code") this.showCode();
    });
    $("assess-download").addEventListener("click", () => this.download("assessment.json"));
    $("assess-download-csv").addEventListener("click", () => this.download("capacity.csv"));
    this.showCode();
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
    const { site = {}, assessment = {}, ...sections } = table;
    this.set("site.code", site.code || "ntc2018");
    this.set("site.soil", site.soil);
    this.set("site.topography", site.topography || "T1");
    this.set("site.spectrum_type", site.spectrum_type ?? 1);
    for (const code of Object.keys(STATES))
      for (const st of STATES[code]) for (const [k] of STATE_KEYS[code]) this.set(`site.${st}.${k}`, site[st]?.[k]);
    for (const k of ["lon", "lat", "VN", "CU"]) this.set(`site.${k}`, site[k]);
    this.set("assessment.confidence_factor", assessment.confidence_factor);
    this.set("assessment.q", assessment.q);
    this.set("assessment.capacity", assessment.capacity || "linear");
    this.showCode();
    const records = Array.isArray(assessment.records) ? assessment.records.length : 0;
    $("assess-note").textContent = records && tower
      ? `${example.path} names a record set (assessment.records) for the non-linear dynamic checks, which the command runs: rocking assess ${example.path}.`
      : "";
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
      for (const st of STATES.ntc2018) for (const [k] of STATE_KEYS.ntc2018) this.set(`site.${st}.${k}`, values[st][k]);
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
      for (const [k] of STATE_KEYS[code]) {
        const v = parseValue(this.field(`site.${st}.${k}`).value);
        if (v !== undefined) t[k] = v;
      }
      if (Object.keys(t).length) site[st] = t;
    }
    const assessment = { capacity: this.field("assessment.capacity").value };
    for (const k of ["confidence_factor", "q"]) {
      const v = parseValue(this.field(`assessment.${k}`).value);
      if (v !== undefined) assessment[k] = v;
    }
    return { ...s, site, assessment };
  }

  /** The page's scenario changed (the tower, the building…): recompute when shown. */
  scenarioChanged() {
    this.changed();
  }

  /** The tab shown or hidden. */
  show(visible) {
    this.visible = visible;
    if (visible && !this.started) {
      this.started = true;
      // The first time: the first example's site (not its tower: the form's stays).
      if (assessments[0]) return this.loadExample(assessments[0], { tower: false });
    }
    if (visible && this.dirty) this.compute();
  }

  changed() {
    this.dirty = true;
    this.panel.classList.add("stale");
    if (this.visible) this.compute();
  }

  async compute() {
    this.dirty = false;
    const id = ++this.requested;
    this.panel.dataset.state = "computing";
    const table = this.table();
    try {
      const result = await this.engine.call({ kind: "assess", table: JSON.stringify(table) });
      if (id !== this.requested) return;
      this.result = result;
      // Kept on the element too, for the page's tests.
      this.panel.assessment = result;
      this.q = table.assessment.q ?? 2;
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

  render() {
    const r = this.result;
    const checks = r.checks;
    const governing = r.governing;
    const cell = (value, digits, bound = false) => `<td class="num" data-value="${value}">${bound ? "≥ " : ""}${sig(value, digits)}</td>`;
    const unit = (u) => u.replace("m/s2", "m/s²");
    const body = checks.map((c) => {
      const m = METHODS[c.method] || { name: c.method, formula: () => "" };
      const isGoverning = governing && governing.limit_state === c.limit_state && governing.method === c.method;
      const bound = c.ag_capacity_is_lower_bound;
      return (
        `<tr data-limit-state="${c.limit_state}" data-method="${c.method}"${isGoverning ? ' class="governing"' : ""}>` +
        `<td>${c.limit_state}</td><td>${m.name}${isGoverning ? " (governing)" : ""}</td>` +
        cell(c.ag_g, 4) +
        cell(c.ag_capacity_g, 4, bound) +
        cell(c.zeta_E, 3, bound) +
        `<td class="${c.holds ? "holds" : "fails"}">${c.holds ? "holds" : "fails"}</td>` +
        `<td class="num" data-value="${c.demand}">${sig(c.demand, 4)} ${unit(c.unit)}</td>` +
        `<td class="num" data-value="${c.capacity}">${sig(c.capacity, 4)} ${unit(c.unit)}</td>` +
        `<td class="formula">${m.formula(this.q)}</td></tr>`
      );
    });
    this.panel.querySelector("#assess-checks tbody").innerHTML = body.join("");
    const g = governing;
    const gm = g && (METHODS[g.method] || { name: g.method, formula: () => "" });
    const line = $("assess-governing");
    line.textContent = g
      ? `Governing: ${g.limit_state} ${gm.name} (${gm.formula(this.q)}): ag capacity ${g.ag_capacity_is_lower_bound ? "≥ " : ""}${sig(g.ag_capacity_g, 4)} g ` +
        `against ag ${sig(g.ag_g, 4)} g, ζ_E = ${g.ag_capacity_is_lower_bound ? "≥ " : ""}${sig(g.zeta_E, 3)}: ${g.holds ? "it holds" : "it FAILS"}.`
      : "";
    line.classList.toggle("danger", !!g && !g.holds);
    const c = r.capacity;
    this.panel.querySelector("#assess-capacity tbody").innerHTML =
      CAPACITY.map(([k, symbol, u, meaning]) => `<tr><td class="label" title="${meaning}">${symbol}</td><td class="num" data-key="${k}" data-value="${c[k]}">${sig(c[k], 4)}</td><td>${u}</td></tr>`).join("") +
      `<tr><td class="label">FC, curve</td><td class="num">${c.confidence_factor}</td><td>${c.curve}</td></tr>`;
    const states = Object.keys(r.sites);
    const fields = SITE_FIELDS.filter(([k]) => states.some((s) => r.sites[s][k] !== undefined));
    this.panel.querySelector("#assess-sites thead").innerHTML = `<tr><th>limit state</th>${fields.map(([, l]) => `<th>${l}</th>`).join("")}</tr>`;
    this.panel.querySelector("#assess-sites tbody").innerHTML = states
      .map((s) => `<tr><td>${s}</td>${fields.map(([k]) => (r.sites[s][k] === undefined ? "<td></td>" : cell(r.sites[s][k], 4))).join("")}</tr>`)
      .join("");
  }

  /** assessment.json (the command's, without a record set) or capacity.csv. */
  download(name) {
    if (!this.result) return;
    const { curve, ms, ...json } = this.result;
    const text = name === "capacity.csv" ? "d_star_m,a_star_m_s2\n" + curve.map(([d, a]) => `${d},${a}`).join("\n") + "\n" : JSON.stringify(json, null, 2) + "\n";
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
}
