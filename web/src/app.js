// The page: a form over a scenario object (the TOML file's keys), recomputed
// on every change through window.rocking; charts (uPlot), the tower's
// animation, the summary, the derived quantities and a sweep's heat map.
import { rocking } from "./rocking.js";
import { drawHeatmap } from "./heatmap.js";
import { Animation } from "./animation.js";
import { Charts } from "./charts.js";
import examples from "../examples.js";

const $ = (id) => document.getElementById(id);

// The form: every key of the scenario file (docs/src/reference/keys.md), per section. `d` is the
// default shown as a placeholder (an empty field is an absent key).
const FIELDS = {
  tower: [
    { k: "section", t: "select", o: ["solid", "hollow"] },
    { k: "width", u: "m" },
    { k: "height", u: "m" },
    { k: "mass", u: "kg" },
    { k: "density", u: "kg/m³" },
    { k: "depth", u: "m", d: "= width" },
    { k: "wall_thickness", u: "m" },
    { k: "inertia_pivot", u: "kg·m²", d: "the section's" },
    { k: "restitution", d: "Housner's" },
  ],
  building: [
    { k: "mass", u: "kg" },
    { k: "mu_static", u: "μs" },
    { k: "mu_kinetic", u: "μk", d: "= μs" },
    { k: "normal_force", t: "select", o: ["constant", "dynamic"] },
  ],
  ground: [
    { k: "type", t: "select", o: ["harmonic", "sine-pulse", "cosine-pulse", "rectangular-pulse", "ricker", "record", "none"] },
    { k: "amplitude", u: "g" },
    { k: "amplitude_ratio", u: "/ tan α" },
    { k: "frequency", u: "Hz" },
    { k: "frequency_ratio", u: "ω / p" },
    { k: "duration", u: "s" },
    { k: "phase", u: "rad", d: "0" },
    { k: "t0", u: "s", d: "1.5 / f" },
    { k: "format", t: "select", o: ["", "at2", "esm", "csv"] },
    { k: "scale", d: "1" },
    { k: "units", t: "select", o: ["", "g", "m/s2", "cm/s2"] },
    { k: "dt", u: "s" },
  ],
  // [ground.vertical]: the vertical ground acceleration, positive upwards,
  // with the types and keys of [ground] (filled in below).
  "ground.vertical": [],
  initial: [
    { k: "theta", u: "rad", d: "0" },
    { k: "theta_over_alpha", d: "0" },
    { k: "theta_dot", u: "rad/s", d: "0" },
  ],
  simulation: [
    { k: "duration", u: "s", d: "20" },
    { k: "g", u: "m/s²", d: "9.81" },
    { k: "output_dt", u: "s", d: "0.005" },
    { k: "rtol", d: "1e-8" },
    { k: "atol", d: "1e-10" },
  ],
};
// The keys of each ground type (crates/rocking-scenario/src/ground.rs).
const GROUND_KEYS = {
  none: ["type"],
  harmonic: ["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio", "duration", "phase"],
  "sine-pulse": ["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio"],
  "cosine-pulse": ["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio"],
  "rectangular-pulse": ["type", "amplitude", "amplitude_ratio", "duration"],
  ricker: ["type", "amplitude", "amplitude_ratio", "frequency", "frequency_ratio", "t0"],
  record: ["type", "file", "text", "format", "scale", "units", "dt"],
};
FIELDS["ground.vertical"] = FIELDS.ground;
const OPTIONAL_SECTIONS = ["tower", "building", "ground.vertical", "initial"];
// A vertical motion switched on from the form starts as this one.
const VERTICAL_START = { type: "harmonic", amplitude: 0.2, frequency: 8.0 };

/** The table of `section` in the scenario (`ground.vertical` lives in `ground`), or undefined. */
function tableOf(section) {
  return section === "ground.vertical" ? scenario.ground?.vertical : scenario[section];
}

/** The table of `section`, created empty if absent. */
function ensureTable(section) {
  if (section !== "ground.vertical") return (scenario[section] = scenario[section] || {});
  scenario.ground = scenario.ground || {};
  return (scenario.ground.vertical = scenario.ground.vertical || {});
}

/** Whether `section` holds a ground motion (its keys follow its type). */
const isMotion = (section) => section === "ground" || section === "ground.vertical";

let scenario = {};
let result = null;
let removed = {}; // sections switched off, kept to switch them back on
let recordName = "";
let sweepCsv = "";
const charts = new Charts($("charts"));
const animation = new Animation($("tower-canvas"), $("time"), $("time-label"), $("play"));

function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
  $("results").classList.toggle("stale", !!message);
}

/** A field's text as a value: a number if it reads as one, else the text (the engine names the key and the type). */
function parseValue(text) {
  const s = text.trim();
  if (s === "") return undefined;
  const x = Number(s);
  return Number.isFinite(x) ? x : s;
}

function buildForm() {
  const form = $("form");
  form.replaceChildren();
  for (const [section, fields] of Object.entries(FIELDS)) {
    const set = document.createElement("fieldset");
    const legend = document.createElement("legend");
    const present = tableOf(section) !== undefined;
    if (OPTIONAL_SECTIONS.includes(section)) {
      const box = document.createElement("input");
      box.type = "checkbox";
      box.checked = present;
      box.id = `has-${section}`;
      box.addEventListener("change", () => toggleSection(section, box.checked));
      legend.append(box, ` [${section}]`);
    } else {
      legend.textContent = `[${section}]`;
    }
    set.append(legend);
    const table = tableOf(section) || {};
    const type = isMotion(section) ? table.type || "harmonic" : null;
    if (present || !OPTIONAL_SECTIONS.includes(section)) {
      for (const f of fields) {
        if (type && !GROUND_KEYS[type]?.includes(f.k)) continue;
        set.append(field(section, f, table[f.k]));
      }
    }
    form.append(set);
  }
}

function field(section, f, value) {
  const label = document.createElement("label");
  label.className = "field";
  const name = document.createElement("span");
  name.textContent = f.k;
  let input;
  if (f.t === "select") {
    input = document.createElement("select");
    for (const o of f.o) input.append(new Option(o === "" ? "(guess)" : o, o));
    input.value = value === undefined ? f.o[0] : String(value);
  } else {
    input = document.createElement("input");
    input.type = "text";
    input.inputMode = "decimal";
    input.placeholder = f.d || "";
    input.value = value === undefined ? "" : String(value);
  }
  input.name = `${section}.${f.k}`;
  input.addEventListener(f.t === "select" ? "change" : "input", () => {
    const table = ensureTable(section);
    const v = f.t === "select" ? input.value || undefined : parseValue(input.value);
    if (v === undefined) delete table[f.k];
    else table[f.k] = v;
    if (isMotion(section) && f.k === "type") {
      // The keys of another type go; the vertical table is not a key of [ground]'s type.
      for (const k of Object.keys(table)) if (!GROUND_KEYS[v].includes(k) && k !== "vertical") delete table[k];
      buildForm();
    }
    recompute();
  });
  const unit = document.createElement("span");
  unit.className = "unit";
  unit.textContent = f.u || "";
  label.append(name, input, unit);
  return label;
}

function toggleSection(section, on) {
  if (section === "ground.vertical") {
    scenario.ground = scenario.ground || {};
    if (on) scenario.ground.vertical = removed[section] || { ...VERTICAL_START };
    else {
      removed[section] = scenario.ground.vertical;
      delete scenario.ground.vertical;
    }
  } else if (on) {
    scenario[section] = removed[section] || {};
  } else {
    removed[section] = scenario[section];
    delete scenario[section];
  }
  buildForm();
  recompute();
}

let pending = false;
function recompute() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    computeNow();
  });
}

function computeNow() {
  saveToUrl();
  try {
    result = rocking.run(scenario);
    const derived = rocking.check(scenario);
    showError("");
    result.gravity = derived.g_m_s2;
    charts.update(result);
    animation.update(scenario, result);
    fillTable($("summary"), result.summary);
    fillTable($("check"), derived);
    $("status").textContent = `Computed in ${(result.summary.wall_time_s * 1000).toFixed(1)} ms.`;
  } catch (e) {
    showError(e.message);
  }
}

/** The unit of a summary or check field, from its name's suffix. */
function unitOf(key) {
  const suffixes = [
    ["_m_s2", "m/s²"], ["_rad_s", "rad/s"], ["_kg_m2", "kg·m²"], ["_rad", "rad"], ["_deg", "°"], ["_kg", "kg"],
    ["_hz", "Hz"], ["_g", "g"], ["_m", "m"], ["_s", "s"],
  ];
  if (key.startsWith("time_in_regime_s.")) return "s";
  const hit = suffixes.find(([s]) => key.endsWith(s));
  return hit ? hit[1] : "";
}

function format(v) {
  if (v === null || v === undefined) return "—";
  if (typeof v === "number") return Number.isInteger(v) ? String(v) : Number(v.toPrecision(6)).toString();
  return String(v);
}

function flatten(obj, prefix = "", out = []) {
  for (const [k, v] of Object.entries(obj)) {
    const key = prefix ? `${prefix}.${k}` : k;
    if (v && typeof v === "object" && !Array.isArray(v)) flatten(v, key, out);
    else out.push([key, v]);
  }
  return out;
}

function fillTable(table, obj) {
  const body = table.tBodies[0];
  body.replaceChildren();
  for (const [key, v] of flatten(obj)) {
    const tr = body.insertRow();
    tr.dataset.key = key;
    tr.insertCell().textContent = key;
    const cell = tr.insertCell();
    cell.className = "num";
    cell.textContent = Array.isArray(v) ? JSON.stringify(v) : format(v);
    cell.dataset.value = JSON.stringify(v);
    tr.insertCell().textContent = unitOf(key);
  }
}

// ---- the scenario in the URL ----
function saveToUrl() {
  const shared = structuredClone(scenario);
  // A record's content does not fit a link: the link carries the other keys.
  if (shared.ground) delete shared.ground.text;
  history.replaceState(null, "", "#" + encodeURIComponent(JSON.stringify(shared)));
}

function loadFromUrl() {
  if (location.hash.length < 2) return false;
  try {
    scenario = JSON.parse(decodeURIComponent(location.hash.slice(1)));
    return true;
  } catch {
    showError("the link's scenario is not valid JSON");
    return false;
  }
}

// ---- examples, files, records ----
function loadToml(text, path) {
  try {
    const table = rocking.fromToml(text);
    const sweep = table.sweep;
    delete table.sweep;
    scenario = table;
    removed = {};
    if (sweep) setAxes(sweep);
    buildForm();
    recompute();
  } catch (e) {
    showError(`${path}: ${e.message.replace(/^scenario\.toml: /, "")}`);
  }
}

function loadRecord(name, text) {
  const ground = scenario.ground || {};
  const keep = {};
  for (const k of ["format", "scale", "units", "dt"]) if (ground.type === "record" && ground[k] !== undefined) keep[k] = ground[k];
  // A vertical motion stays: the record is the horizontal one.
  scenario.ground = { type: "record", text, ...keep, ...(ground.vertical ? { vertical: ground.vertical } : {}) };
  recordName = name;
  $("record-name").textContent = `record: ${name} (${text.length} characters)`;
  buildForm();
  recompute();
}

function setupFiles() {
  const select = $("example");
  examples.forEach((e, i) => select.append(new Option(e.path, String(i))));
  select.addEventListener("change", () => {
    const e = examples[Number(select.value)];
    if (e) loadToml(e.toml, e.path);
  });
  $("open-toml").addEventListener("change", async (ev) => {
    const file = ev.target.files[0];
    if (file) loadToml(await file.text(), file.name);
  });
  $("record-file").addEventListener("change", async (ev) => {
    const file = ev.target.files[0];
    if (file) loadRecord(file.name, await file.text());
  });
  const drop = $("drop");
  drop.addEventListener("dragover", (e) => {
    e.preventDefault();
    drop.classList.add("over");
  });
  drop.addEventListener("dragleave", () => drop.classList.remove("over"));
  drop.addEventListener("drop", async (e) => {
    e.preventDefault();
    drop.classList.remove("over");
    const file = e.dataTransfer.files[0];
    if (file) loadRecord(file.name, await file.text());
  });
}

// ---- downloads ----
function csv(columns, rows) {
  return [columns.join(","), ...rows.map((r) => r.map((v) => (v === null || v === undefined ? "" : String(v))).join(","))].join("\n") + "\n";
}

function download(name) {
  let text;
  if (name === "scenario.toml") text = rocking.toToml(scenario);
  else if (name === "sweep.csv") text = sweepCsv;
  else if (!result) return;
  else if (name === "summary.json") text = JSON.stringify(result.summary, null, 2) + "\n";
  else if (name === "history.csv") {
    const cols = Object.keys(result.history);
    const n = result.history.t.length;
    text = csv(cols, Array.from({ length: n }, (_, i) => cols.map((c) => result.history[c][i])));
  } else if (name === "events.csv") {
    const cols = result.eventColumns;
    text = csv(cols, result.events.map((e) => cols.map((c) => e[c])));
  }
  if (!text) return;
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// ---- the sweep view ----
let numericKeys = [];
function axisEditor(i, spec) {
  const box = document.createElement("div");
  box.className = "axis";
  const key = document.createElement("select");
  key.id = `axis${i}-key`;
  if (i === 1) key.append(new Option("(none)", ""));
  for (const k of numericKeys) key.append(new Option(k, k));
  key.value = spec.key;
  const input = (name, value) => {
    const el = document.createElement("input");
    el.id = `axis${i}-${name}`;
    el.value = value;
    const label = document.createElement("label");
    label.append(` ${name} `, el);
    return label;
  };
  box.append(`axis ${i + 1}: `, key, input("from", spec.from), input("to", spec.to), input("steps", spec.steps));
  return box;
}

function setAxes(sweep) {
  const specs = Object.entries(sweep).map(([key, v]) => {
    if (Array.isArray(v)) return { key, from: v[0], to: v[v.length - 1], steps: v.length };
    const steps = v.steps ?? Math.round((v.to - v.from) / v.step) + 1;
    return { key, from: v.from, to: v.to, steps };
  });
  while (specs.length < 2) specs.push({ key: "", from: "", to: "", steps: "" });
  const axes = $("axes");
  axes.replaceChildren(axisEditor(0, specs[0]), axisEditor(1, specs[1]));
}

function readAxes() {
  const axes = {};
  for (const i of [0, 1]) {
    const key = $(`axis${i}-key`).value;
    if (!key) continue;
    axes[key] = { from: parseValue($(`axis${i}-from`).value), to: parseValue($(`axis${i}-to`).value), steps: parseValue($(`axis${i}-steps`).value) };
  }
  return axes;
}

let controller = null;
async function runSweep() {
  const axes = readAxes();
  controller = new AbortController();
  $("sweep-run").disabled = true;
  $("sweep-cancel").disabled = false;
  const progress = $("sweep-progress");
  const label = $("sweep-label");
  progress.value = 0;
  const start = performance.now();
  try {
    const columns = await rocking.sweep(scenario, axes, {
      signal: controller.signal,
      onProgress: (done, total) => {
        progress.max = total;
        progress.value = done;
        label.textContent = `${done} / ${total} cases`;
      },
    });
    sweepCsv = columns.csv;
    const n = columns[Object.keys(columns)[0]].length;
    label.textContent = `${n} cases in ${((performance.now() - start) / 1000).toFixed(2)} s`;
    label.dataset.done = "true";
    drawHeatmap($("heatmap"), columns, Object.keys(axes));
  } catch (e) {
    label.textContent = e.message;
    if (e.message !== "sweep cancelled") showError(e.message);
  } finally {
    $("sweep-run").disabled = false;
    $("sweep-cancel").disabled = true;
  }
}

async function main() {
  setupFiles();
  for (const b of document.querySelectorAll("[data-download]")) b.addEventListener("click", () => download(b.dataset.download));
  $("copy-link").addEventListener("click", () => navigator.clipboard?.writeText(location.href));
  $("sweep-run").addEventListener("click", runSweep);
  $("sweep-cancel").addEventListener("click", () => controller?.abort());
  try {
    await rocking.ready;
  } catch (e) {
    showError(`the engine did not load: ${e.message}`);
    return;
  }
  const skip = ["name", "tower.section", "ground.type", "ground.file", "ground.text", "ground.format", "ground.units", "building.normal_force"];
  numericKeys = (await rocking.sweepableKeys()).filter((k) => !skip.includes(k));
  setAxes({ "ground.frequency": { from: 3, to: 7, steps: 21 }, "ground.amplitude": { from: 0.5, to: 2, steps: 4 } });
  $("status").textContent = "Engine loaded.";
  if (loadFromUrl()) {
    buildForm();
    computeNow();
  } else {
    const first = examples.find((e) => e.path === "examples/tower-on-church.toml") || examples[0];
    if (first) loadToml(first.toml, first.path);
  }
}

main();
