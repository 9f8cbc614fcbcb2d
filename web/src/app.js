// The page: a form over a scenario object (the TOML file's keys), recomputed
// on every change in a Web Worker (window.rocking.runInWorker); errors at
// their field; charts (uPlot), the tower's animation, the end of the run in
// words, the summary, the derived quantities and a sweep's heat map.
import { rocking } from "./rocking.js";
import { drawHeatmap } from "./heatmap.js";
import { Animation } from "./animation.js";
import { Charts } from "./charts.js";
import { SpectrumView } from "./spectrum.js";
import { AssessView, keyOf } from "./assess.js";
import { setupTabs } from "./tabs.js";
import { TownView } from "./town.js";
import examples, { records } from "../examples.js";

const $ = (id) => document.getElementById(id);

// The form: the keys of the scenario file that have a field, per section, as
// { k: name, u: unit or symbol, d: placeholder, t: "select", o: options };
// and the keys each ground type takes. Both are read at load from the keys'
// description (the engine's `keys()`, as `rocking keys --json` prints it;
// crates/rocking-scenario/src/keys.rs), by formFields().
let FIELDS = {};
let GROUND_KEYS = {};
// The fields of each [[block]] on the tower (every number and string of the
// section, the block's name first), from the same description.
let BLOCK_FIELDS = [];
// The keys' descriptions by dotted key.
let keyInfo = new Map();
// A choice that decides which of its section's fields apply leads the section.
const LEADS = ["tower.section"];

/** What is shown beside a key's field: its unit, or a dimensionless number's symbol (`μs`) unless that is its name. */
function shownUnit(k) {
  return k.unit || (k.kind === "number" && k.symbol !== k.name ? k.symbol : "");
}

/** The description of a dotted key; a key of the vertical motion is described by [ground]'s. */
function describeKey(key) {
  const blockKey = Array.isArray(scenario.block) && scenario.block.some((_, i) => key.startsWith(`${blockName(i)}.`)) ? `${BLOCK}.${key.slice(key.indexOf(".") + 1)}` : key;
  return keyInfo.get(blockKey) || keyInfo.get(key.replace(/^ground\.vertical\./, "ground."));
}

/**
 * The form's fields and each ground type's keys, from the keys' description:
 * the numbers and strings of each section that have a field (`on_form`), in
 * the description's order; a table (`ground.vertical`) is a section of its
 * own with the fields of the section it is in.
 */
function formFields(keys) {
  const fields = {};
  const groundKeys = {};
  const blockFields = [];
  for (const k of keys) {
    if (k.section === null) continue;
    if (k.section === BLOCK) {
      if (k.kind === "number" || k.kind === "string") blockFields.push(fieldOf(k));
      continue;
    }
    for (const type of k.types || []) (groundKeys[type] ??= []).push(k.name);
    fields[k.section] ??= [];
    if (k.kind === "table") fields[k.key] = k.section;
    if (!k.on_form || !k.sweepable) continue;
    const f = fieldOf(k);
    if (LEADS.includes(k.key)) fields[k.section].unshift(f);
    else fields[k.section].push(f);
  }
  for (const [section, v] of Object.entries(fields)) if (typeof v === "string") fields[section] = fields[v];
  // A section without a field on the form has no fieldset (the blocks have their own, blockSets).
  for (const [section, v] of Object.entries(fields)) if (v.length === 0) delete fields[section];
  return { fields, groundKeys, blockFields };
}

/** A key's field: its name, unit, placeholder, choices if it has them, and whether its text is kept as text (`s`: a string key). */
function fieldOf(k) {
  const f = { k: k.name, u: shownUnit(k), d: k.placeholder, s: k.kind === "string" };
  if (k.choices.length) Object.assign(f, { t: "select", o: k.placeholder ? ["", ...k.choices] : k.choices, u: "" });
  return f;
}

// The section of the blocks on the tower, a list of tables (`[[block]]`).
const BLOCK = "block";
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
// The record of each motion section ("ground", "ground.vertical"): the name it
// was given (a file's, or a bundled record's path), shown and put in links.
let recordNames = {};
// The motion sections whose record a link or a TOML file names but the page
// does not hold: it asks for the file and runs once given.
let missingRecords = {};
let sweepCsv = "";
const charts = new Charts($("theta-chart"), $("charts"));
const spectrum = new SpectrumView($("record-view"));
let assessView = null; // the assess tab, once the engine has loaded
const animation = new Animation($("tower-canvas"), {
  slider: $("time"),
  label: $("time-label"),
  button: $("play"),
  timeline: $("timeline"),
  theta: $("exaggerate-theta"),
  slip: $("exaggerate-slip"),
  speed: $("speed"),
});

/**
 * Shows an error line (or clears it with ""): in the banner (kept in view),
 * and beside the field it names, which is marked invalid; the results of the
 * last valid input stay, marked stale.
 */
function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
  for (const el of document.querySelectorAll("[aria-invalid]")) {
    el.removeAttribute("aria-invalid");
    el.removeAttribute("aria-describedby");
  }
  for (const el of document.querySelectorAll(".field-error")) el.remove();
  if (message) {
    const key = keyOf(message);
    const input = key && document.querySelector(`[name="${CSS.escape(key)}"]`);
    if (input) {
      input.setAttribute("aria-invalid", "true");
      const note = document.createElement("div");
      note.className = "field-error";
      note.id = `error-${key}`;
      note.textContent = message.slice(message.indexOf(key) + key.length + 2);
      input.closest(".field").after(note);
      input.setAttribute("aria-describedby", note.id);
    }
    markStale("Not computed: the input has an error (the results shown are of the last valid input).");
  }
}

/** Marks the shown results as not those of the inputs, with why. */
function markStale(why) {
  $("results").classList.add("stale");
  $("status").textContent = why;
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
    if (section === BLOCK) continue;
    const set = document.createElement("fieldset");
    const legend = document.createElement("legend");
    const present = tableOf(section) !== undefined;
    if (OPTIONAL_SECTIONS.includes(section)) {
      const box = document.createElement("input");
      box.type = "checkbox";
      box.checked = present;
      box.id = `has-${section}`;
      box.addEventListener("change", () => toggleSection(section, box.checked));
      const label = document.createElement("label");
      label.append(box, ` [${section}]`);
      box.setAttribute("aria-label", `include the [${section}] table`);
      legend.append(label);
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
  if (scenario.tower) form.append(...blockSets());
  refreshAxisKeys();
}

/** The name of block `i` (from 0) on the tower: its `name`, or the default `block2`, `block3`, … */
const blockName = (i) => (typeof scenario.block?.[i]?.name === "string" && scenario.block[i].name) || `block${i + 2}`;

/**
 * The fieldsets of the blocks on the tower, each with its fields (named as
 * errors name them: `belfry.width`) and a button that removes it, and the
 * button that adds one on top.
 */
function blockSets() {
  const blocks = Array.isArray(scenario.block) ? scenario.block : [];
  const sets = blocks.map((table, i) => {
    const set = document.createElement("fieldset");
    set.className = "block";
    const legend = document.createElement("legend");
    legend.textContent = `[[block]] ${blockName(i)}`;
    const remove = document.createElement("button");
    remove.type = "button";
    remove.textContent = "remove";
    remove.setAttribute("aria-label", `remove the block ${blockName(i)}`);
    remove.addEventListener("click", () => {
      scenario.block.splice(i, 1);
      if (!scenario.block.length) delete scenario.block;
      buildForm();
      recompute();
    });
    legend.append(" ", remove);
    set.append(legend);
    for (const f of BLOCK_FIELDS) {
      const input = field(BLOCK, f, table[f.k], { table: () => table, name: f.k === "name" ? `block[${i + 1}].name` : `${blockName(i)}.${f.k}` });
      set.append(input);
    }
    return set;
  });
  const add = document.createElement("button");
  add.type = "button";
  add.id = "add-block";
  add.textContent = "add a block on top (a belfry)";
  add.addEventListener("click", () => {
    scenario.block = blocks;
    scenario.block.push(newBlock(blocks));
    buildForm();
    recompute();
  });
  return [...sets, add];
}

/**
 * A block to put on top of `blocks` (on the tower when there is none): 60 %
 * as wide as the block below, 40 % of the tower's height, a fifth of its
 * mass (or its density); a start the user then edits.
 */
function newBlock(blocks) {
  const tower = scenario.tower;
  const below = blocks.length ? blocks[blocks.length - 1] : tower;
  const round = (x) => Number(x.toPrecision(2));
  const block = { name: blocks.length ? `block${blocks.length + 2}` : "belfry" };
  block.width = round(0.6 * (typeof below.width === "number" ? below.width : 4));
  block.height = round(0.4 * (typeof tower.height === "number" ? tower.height : 12));
  if (typeof tower.mass === "number") block.mass = round(0.2 * tower.mass);
  else block.density = typeof tower.density === "number" ? tower.density : 1800;
  return block;
}

/**
 * A key's field: `where` gives the table it edits and the input's name
 * (default: the section's table, `section.key`).
 */
function field(section, f, value, where = {}) {
  const tableOfField = where.table || (() => ensureTable(section));
  const label = document.createElement("label");
  label.className = "field";
  const name = document.createElement("span");
  name.textContent = f.k;
  let input;
  if (f.t === "select") {
    input = document.createElement("select");
    for (const o of f.o) input.append(new Option(o === "" ? `(${f.d})` : o, o));
    input.value = value === undefined ? f.o[0] : String(value);
  } else {
    input = document.createElement("input");
    input.type = "text";
    input.inputMode = "decimal";
    input.placeholder = f.d || "";
    input.value = value === undefined ? "" : String(value);
  }
  input.name = where.name || `${section}.${f.k}`;
  input.id = `field-${input.name}`;
  input.addEventListener(f.t === "select" ? "change" : "input", () => {
    const table = tableOfField();
    // A string key's text stays text (a block named "3" is told why that is no name, not that 3 is a number).
    const v = f.t === "select" ? input.value || undefined : f.s ? input.value.trim() || undefined : parseValue(input.value);
    if (v === undefined) delete table[f.k];
    else table[f.k] = v;
    if (isMotion(section) && f.k === "type") {
      // The keys of another type go; the vertical table is not a key of [ground]'s type.
      for (const k of Object.keys(table)) if (!GROUND_KEYS[v].includes(k) && k !== "vertical") delete table[k];
      buildForm();
      if (v === "record" && table.text === undefined) missingRecords[section] = "a record file";
      else delete missingRecords[section];
    }
    // While a number is being typed its intermediate values ("0" on the way
    // to "0.3") are not errors: an error waits until the typing pauses or the
    // field is left.
    recompute({ typing: f.t !== "select" });
  });
  if (f.t !== "select") {
    input.addEventListener("change", () => {
      if (section === "building" && f.k === "mu_static") lowerKineticFriction();
      // A block's new name names its fields.
      if (section === BLOCK && f.k === "name") buildForm();
      recompute();
    });
  }
  const unit = document.createElement("span");
  unit.className = "unit";
  unit.textContent = f.u || "";
  label.append(name, input, unit);
  return label;
}

/**
 * μk ≤ μs: a μs lowered below μk (once its field is left) lowers μk with it,
 * said beside the μk field.
 */
function lowerKineticFriction() {
  const b = scenario.building;
  if (!b || typeof b.mu_static !== "number" || typeof b.mu_kinetic !== "number" || b.mu_kinetic <= b.mu_static) return;
  b.mu_kinetic = b.mu_static;
  const input = document.querySelector('[name="building.mu_kinetic"]');
  input.value = String(b.mu_static);
  const note = document.createElement("div");
  note.className = "field-note";
  note.textContent = "lowered to μs (μk ≤ μs)";
  document.querySelector(".field-note")?.remove();
  input.closest(".field").after(note);
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
let typing = false;
let errorTimer = 0;
// The cost of a run per history row (one per output_dt), which sets the
// cost of a long run: measured in headless Chromium on this project's 2-core
// machine with the default example at 20,000 s (4,000,001 rows): 5.5–6.9 s
// in the worker (1.4–1.7 µs a row), and the browser's memory 1.86 GB above
// its level before the run (465 bytes a row: the engine's samples and
// columns, their copies in JavaScript, the regime's text).
const COST = { row_s: 1.7e-6, bytes_per_row: 470 };
/** The runs the user has confirmed despite their cost (their JSON text). */
let confirmed = "";

/** Recomputes at the next frame; `typing`: an error of this change waits (see field()). */
function recompute({ typing: isTyping = false } = {}) {
  typing = isTyping;
  setState("computing");
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    computeNow();
  });
}

/** The number of history rows, time and memory a run of the scenario would take, from COST. */
function runEstimate(s) {
  const sim = s.simulation || {};
  const duration = typeof sim.duration === "number" ? sim.duration : 20;
  const dt = typeof sim.output_dt === "number" ? sim.output_dt : 0.005;
  const rows = dt > 0 ? Math.floor(duration / dt) + 1 : 0;
  return { rows, seconds: rows * COST.row_s, bytes: rows * COST.bytes_per_row };
}

/** Asks before a run that would take over 2 s or 400 MB; true if it may go. */
function mayRun(text) {
  const e = runEstimate(scenario);
  const box = $("run-warning");
  if ((e.seconds <= 2 && e.bytes <= 4e8) || confirmed === text) {
    box.hidden = true;
    return true;
  }
  $("run-warning-text").textContent =
    `This run writes ${e.rows.toLocaleString("en")} history rows (simulation.duration / output_dt): ` +
    `about ${e.seconds.toFixed(0)} s and ${(e.bytes / 1e6).toFixed(0)} MB in this browser. A larger output_dt or a shorter duration is quicker.`;
  box.hidden = false;
  $("run-anyway").onclick = () => {
    confirmed = text;
    box.hidden = true;
    computeNow();
  };
  markStale("Waiting: this run would take long (see above).");
  setState("waiting");
  return false;
}

/**
 * The page's state, on <body data-state>: "computing", "done" (the results
 * are those of the inputs), "error", or "waiting" (for a record file, or for
 * a long run to be confirmed).
 */
function setState(state) {
  document.body.dataset.state = state;
}

let shown = 0; // the number of the request whose results are shown
let requested = 0;
async function computeNow() {
  saveToUrl();
  markSweepStale();
  assessView?.scenarioChanged();
  const wanted = Object.keys(missingRecords);
  showRecordPrompt();
  if (wanted.length) {
    markStale("Waiting for the record file (see the box under the form).");
    setState("waiting");
    return;
  }
  const text = JSON.stringify(scenario);
  if (!mayRun(text)) return;
  const id = ++requested;
  const wasTyping = typing;
  setState("computing");
  $("status").textContent = "Computing…";
  try {
    const out = await rocking.runInWorker(scenario);
    if (id < shown) return;
    shown = id;
    clearTimeout(errorTimer);
    showError("");
    result = out;
    result.gravity = out.derived.g_m_s2;
    charts.update(result);
    animation.update(scenario, result);
    fillTable($("summary"), result.summary);
    const verdict = verdictOf(result);
    $("verdict").textContent = verdict;
    $("verdict").hidden = !verdict;
    $("verdict").dataset.endState = result.summary.end_state || "";
    const falls = ["overturned", "beyond_stability_limit"].includes(result.summary.end_state) || result.summary.will_overturn === true;
    $("verdict").classList.toggle("danger", falls);
    // Each block's quantities under its name (blocks.belfry.alpha_rad).
    const { blocks, ...derived } = out.derived;
    if (blocks?.length) derived.blocks = Object.fromEntries(blocks.map(({ name, ...rest }) => [name, rest]));
    fillTable($("check"), derived);
    spectrum.update(scenario, recordNames.ground);
    $("results").classList.remove("stale");
    $("status").textContent = `Computed in ${(result.summary.wall_time_s * 1000).toFixed(1)} ms.`;
    if (id === requested) setState("done");
  } catch (e) {
    if (e.superseded || id < shown) return;
    shown = id;
    clearTimeout(errorTimer);
    if (id === requested) setState("error");
    if (wasTyping) errorTimer = setTimeout(() => showError(e.message), 800);
    else showError(e.message);
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

// The summary's fields as the outputs reference describes them, and the derived quantities (name → { unit, meaning }).
let fieldInfo = new Map();

/** A summary field's description; a block's (`belfry_impacts`) is that of `<name>_impacts`, its name first. */
function infoOf(key) {
  const info = fieldInfo.get(key);
  if (info) return info;
  const name = (result?.blocks || []).find((b) => key.startsWith(`${b}_`));
  const block = name && fieldInfo.get(`<name>_${key.slice(name.length + 1)}`);
  return block && { ...block, block: name };
}

/** A field's plain-language label: its meaning from the outputs reference, else its key. */
function labelOf(key) {
  const meaning = infoOf(key)?.meaning;
  if (!meaning) return key;
  // The reference's first clause, without its Markdown: "the tower at the end: `rest`, …" → "The tower at the end".
  // Without a leading condition ("(with [[block]]) the largest …").
  const plain = meaning.replace(/`/g, "").replace(/^\([^)]*\)\s*/, "").split(/[:;(]/)[0].trim();
  const label = plain.charAt(0).toUpperCase() + plain.slice(1);
  const block = infoOf(key).block;
  return block ? `${block}: ${label}` : label;
}

function fillTable(table, obj) {
  const body = table.tBodies[0];
  body.replaceChildren();
  for (const [key, v] of flatten(obj)) {
    const tr = body.insertRow();
    tr.dataset.key = key;
    const name = tr.insertCell();
    name.className = "label";
    name.textContent = labelOf(key);
    const info = infoOf(key);
    if (info) name.title = `${key}: ${info.meaning.replace(/`/g, "")}`;
    const code = document.createElement("code");
    code.textContent = key;
    name.append(" ", code);
    const cell = tr.insertCell();
    cell.className = "num";
    cell.textContent = Array.isArray(v) ? JSON.stringify(v) : format(v);
    cell.dataset.value = JSON.stringify(v);
    tr.insertCell().textContent = info ? info.unit.replace(/^–$/, "") : unitOf(key);
  }
}

/**
 * What the end of the run means for the tower, in words (end_state and
 * will_overturn of the summary; docs/src/model.md, "The end of a run").
 */
function verdictOf(result) {
  const s = result.summary;
  if (!s.end_state) return "";
  const theta = result.history.theta;
  const ratio = s.alpha_rad ? theta[theta.length - 1] / s.alpha_rad : 0;
  const at = `at t = ${format(s.end_time_s)} s`;
  const next = {
    true: " It will overturn: its free motion from there carries it over (no input remains).",
    false: " It will come to rest: its free motion from there does not carry it over.",
    null: " Ground motion remains after the run (or the church still slides): what follows is not decided here; run longer.",
  }[String(s.will_overturn)];
  // With blocks on the tower the free motion's verdict (one block's closed form) is not given.
  const undecided = result.derived?.blocks?.length ? " With blocks on the tower, whether their free motion overturns one is not foretold here (will_overturn is the lone tower's)." : next;
  switch (s.end_state) {
    case "overturned":
      return `The tower overturned at t = ${format(s.overturn_time_s)} s.`;
    case "beyond_stability_limit":
      return `The tower ends past its stability limit (θ/α = ${format(ratio)} ${at}), not yet overturned.${s.will_overturn === null ? undecided : next}`;
    case "rocking":
      return `The tower is still rocking at the end (θ/α = ${format(ratio)} ${at}).${s.will_overturn === null ? undecided : next}`;
    default:
      return `The tower is at rest at the end (${at}).${s.will_overturn === null ? undecided : ""}`;
  }
}

// ---- the scenario in the URL ----
/** The motion tables of a scenario, by section. */
function motionTables(s) {
  return [["ground", s.ground], ["ground.vertical", s.ground?.vertical]].filter(([, t]) => t && typeof t === "object");
}

function saveToUrl() {
  const shared = structuredClone(scenario);
  // A record's content does not fit a link: the link names its file instead
  // (a bundled record's path, which the page finds again; else the file's
  // name, which the page asks for).
  for (const [section, t] of motionTables(shared)) {
    if (t.text !== undefined) {
      delete t.text;
      t.file = recordNames[section] || "record";
    } else if (missingRecords[section] && t.type === "record") t.file = missingRecords[section];
  }
  history.replaceState(null, "", "#" + encodeURIComponent(JSON.stringify(shared)));
}

function loadFromUrl() {
  if (location.hash.length < 2) return false;
  try {
    scenario = JSON.parse(decodeURIComponent(location.hash.slice(1)));
  } catch {
    showError("the link's scenario is not valid JSON");
    return false;
  }
  attachRecords("");
  selectExample(null);
  return true;
}

/** `rel` taken from directory `dir` ("a/b" + "../c" → "a/c"). */
function joinPath(dir, rel) {
  const parts = dir ? dir.split("/") : [];
  for (const p of rel.split("/")) {
    if (p === "..") parts.pop();
    else if (p !== "." && p !== "") parts.push(p);
  }
  return parts.join("/");
}

/**
 * Puts each record a motion table names by `file` (relative to `dir`) in
 * place as its text when the page holds it (the examples' records); the
 * others are asked for (missingRecords).
 */
function attachRecords(dir) {
  recordNames = {};
  missingRecords = {};
  for (const [section, t] of motionTables(scenario)) {
    if (t.type !== "record" || t.text !== undefined) continue;
    const file = typeof t.file === "string" ? t.file : "";
    const path = [joinPath(dir, file), file].find((p) => p in records);
    delete t.file;
    if (path) {
      t.text = records[path];
      recordNames[section] = path;
    } else missingRecords[section] = file || "a record file";
  }
}

/** The box that asks for the record files a case needs, and names those it has. */
function showRecordPrompt() {
  const wanted = Object.entries(missingRecords);
  const drop = $("drop");
  drop.classList.toggle("needed", wanted.length > 0);
  $("record-needed").textContent = wanted.length
    ? `This case needs its record: ${wanted.map(([s, f]) => `${f} (${s})`).join(", ")}. Choose the file or drop it here; it runs once given.`
    : "";
  $("record-name").textContent = Object.entries(recordNames)
    .map(([s, n]) => `${s}: record ${n}${tableOf(s)?.text ? ` (${tableOf(s).text.length} characters)` : ""}`)
    .join("; ");
}

/** Shows example `index` (a number) as the one loaded, or none. */
function selectExample(index) {
  $("example").value = index === null ? "" : String(index);
}

// ---- examples, files, records ----
/** Loads a TOML file's text; `path` names it in errors and resolves the record files it names. */
function loadToml(text, path) {
  try {
    const table = rocking.fromToml(text);
    const sweep = table.sweep;
    delete table.sweep;
    scenario = table;
    removed = {};
    attachRecords(path.includes("/") ? path.slice(0, path.lastIndexOf("/")) : "");
    if (sweep) setAxes(sweep);
    buildForm();
    recompute();
  } catch (e) {
    showError(`${path}: ${e.message.replace(/^scenario\.toml: /, "")}`);
  }
}

/**
 * A record file's text given on the page: the record a case waits for (the
 * horizontal one first), else the horizontal motion, which becomes this
 * record (its format, scale, units and dt kept if it was one).
 */
function loadRecord(name, text) {
  const section = Object.keys(missingRecords)[0];
  if (section) {
    delete missingRecords[section];
    ensureTable(section).text = text;
  } else {
    const ground = scenario.ground || {};
    const keep = {};
    // The record's own fields (format, scale, units, dt).
    const own = FIELDS.ground.map((f) => f.k).filter((k) => k !== "type" && GROUND_KEYS.record.includes(k));
    for (const k of own) if (ground.type === "record" && ground[k] !== undefined) keep[k] = ground[k];
    // A vertical motion stays: the record is the horizontal one.
    scenario.ground = { type: "record", text, ...keep, ...(ground.vertical ? { vertical: ground.vertical } : {}) };
  }
  recordNames[section || "ground"] = name;
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
  $("open-toml-button").addEventListener("click", () => $("open-toml").click());
  $("record-button").addEventListener("click", () => $("record-file").click());
  $("open-toml").addEventListener("change", async (ev) => {
    const file = ev.target.files[0];
    if (file) {
      selectExample(null);
      loadToml(await file.text(), file.name);
    }
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

async function download(name) {
  let text;
  if (name === "scenario.toml") text = rocking.toToml(scenario);
  else if (name === "sweep.csv") text = sweepCsv;
  else if (!result) return;
  else if (name === "summary.json") text = JSON.stringify(result.summary, null, 2) + "\n";
  else if (name === "history.csv") {
    // Written by the run's worker, which holds every row of a long history.
    text = await rocking.historyCsv();
  } else if (name === "events.csv") {
    const cols = result.eventColumns;
    text = csv(cols, result.events.map((e) => cols.map((c) => e[c])));
  }
  if (!text) return;
  const a = document.createElement("a");
  a.href = URL.createObjectURL(text instanceof Blob ? text : new Blob([text], { type: "text/plain" }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// ---- the sweep view ----
let numericKeys = [];

/** The keys the sweep's axes offer: the numeric ones, and each block's by its name (`belfry.width`). */
function axisKeys() {
  const blocks = Array.isArray(scenario.block) ? scenario.block : [];
  const own = BLOCK_FIELDS.filter((f) => f.t !== "select" && describeKey(`${BLOCK}.${f.k}`)?.kind === "number");
  return [...numericKeys, ...blocks.flatMap((_, i) => own.map((f) => `${blockName(i)}.${f.k}`))];
}

/** The axes' key lists after the blocks changed, each axis keeping its key while it is offered. */
function refreshAxisKeys() {
  for (const i of [0, 1]) {
    const select = $(`axis${i}-key`);
    if (!select) continue;
    const value = select.value;
    const keys = axisKeys();
    select.replaceChildren(...(i === 1 ? [new Option("(none)", "")] : []), ...keys.map((k) => new Option(k, k)));
    select.value = keys.includes(value) || value === "" ? value : select.options[0].value;
  }
}
function axisEditor(i, spec) {
  const box = document.createElement("div");
  box.className = "axis";
  const key = document.createElement("select");
  key.id = `axis${i}-key`;
  key.setAttribute("aria-label", `axis ${i + 1}: the swept key`);
  if (i === 1) key.append(new Option("(none)", ""));
  for (const k of axisKeys()) key.append(new Option(k, k));
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

// The cost of a sweep's case per simulated second, measured with
// web/tests/bench.py (README, "The page in the browser": 1,000 cases of 20 s
// in 0.993 s in one worker): 5e-5 s.
const SWEEP_COST_S = 5e-5;
let sweepShown = null; // { columns, keys, labels, scenario (JSON text) } of the map drawn
let sweepConfirmed = "";

/** The number of cases of the axes and their estimated time in the worker (s). */
function sweepEstimate(axes) {
  let cases = 1;
  for (const v of Object.values(axes)) cases *= Array.isArray(v) ? v.length : Number(v.steps) || 1;
  const duration = typeof scenario.simulation?.duration === "number" ? scenario.simulation.duration : 20;
  return { cases, seconds: cases * duration * SWEEP_COST_S };
}

/** An axis's name with its unit (the form's), e.g. "ground.frequency (Hz)". */
function axisLabel(key) {
  const k = describeKey(key);
  const unit = k ? shownUnit(k) : "";
  return unit ? `${key} (${unit})` : key;
}

function drawSweep() {
  if (!sweepShown) return;
  const { columns, keys, labels } = sweepShown;
  // Drawn at the width it is shown at (up to 640 px), so that its text stays legible on a phone.
  const canvas = $("heatmap");
  canvas.width = Math.max(320, Math.min(640, $("heatmap-box").clientWidth - 2));
  canvas.height = Math.round(canvas.width * 0.5625);
  const at = drawHeatmap(canvas, columns, keys, labels, $("heatmap-log").checked);
  sweepShown.at = at;
}

/** Marks the drawn map stale when the inputs are no longer those it was run with. */
function markSweepStale() {
  const stale = !!sweepShown && sweepShown.scenario !== JSON.stringify(scenario);
  $("sweep-stale").hidden = !stale;
  $("heatmap-box").classList.toggle("stale", stale);
}

let controller = null;
async function runSweep() {
  const axes = readAxes();
  const estimate = sweepEstimate(axes);
  const text = JSON.stringify([scenario, axes]);
  if ((estimate.cases > 1e4 || estimate.seconds > 30) && sweepConfirmed !== text) {
    $("sweep-warning-text").textContent =
      `This sweep has ${estimate.cases.toLocaleString("en")} cases: about ${Math.ceil(estimate.seconds).toLocaleString("en")} s in this browser (one worker). ` +
      "The command runs it on every core (rocking sweep --threads N).";
    $("sweep-warning").hidden = false;
    $("sweep-anyway").onclick = () => {
      sweepConfirmed = text;
      $("sweep-warning").hidden = true;
      runSweep();
    };
    return;
  }
  $("sweep-warning").hidden = true;
  controller = new AbortController();
  $("sweep-run").disabled = true;
  $("sweep-cancel").disabled = false;
  const progress = $("sweep-progress");
  const label = $("sweep-label");
  progress.value = 0;
  delete label.dataset.done;
  const start = performance.now();
  const ran = JSON.stringify(scenario);
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
    const keys = Object.keys(axes);
    sweepShown = { columns, keys, labels: keys.map(axisLabel), scenario: ran };
    drawSweep();
    markSweepStale();
  } catch (e) {
    label.textContent = e.message;
    if (e.message !== "sweep cancelled") showError(e.message);
  } finally {
    $("sweep-run").disabled = false;
    $("sweep-cancel").disabled = true;
  }
}

function setupHeatmap() {
  const canvas = $("heatmap");
  $("heatmap-log").addEventListener("change", drawSweep);
  canvas.addEventListener("mousemove", (e) => {
    const box = canvas.getBoundingClientRect();
    const x = ((e.clientX - box.left) * canvas.width) / box.width;
    const y = ((e.clientY - box.top) * canvas.height) / box.height;
    $("heatmap-tip").textContent = sweepShown?.at?.(x, y) || "";
  });
  canvas.addEventListener("mouseleave", () => ($("heatmap-tip").textContent = ""));
}

async function main() {
  setupFiles();
  for (const b of document.querySelectorAll("[data-download]")) b.addEventListener("click", () => download(b.dataset.download).catch((e) => ($("status").textContent = e.message)));
  $("copy-link").addEventListener("click", () => navigator.clipboard?.writeText(location.href));
  $("sweep-run").addEventListener("click", runSweep);
  setupHeatmap();
  $("sweep-cancel").addEventListener("click", () => controller?.abort());
  try {
    await rocking.ready;
  } catch (e) {
    showError(`the engine did not load: ${e.message}`);
    return;
  }
  const keys = (await rocking.keys()).scenario;
  keyInfo = new Map(keys.map((k) => [k.key, k]));
  ({ fields: FIELDS, groundKeys: GROUND_KEYS, blockFields: BLOCK_FIELDS } = formFields(keys));
  // The axes of the page's sweep are numbers.
  numericKeys = (await rocking.sweepableKeys()).filter((k) => describeKey(k)?.kind === "number");
  fieldInfo = new Map([...(await rocking.derivedFields()), ...(await rocking.summaryFields())].map((f) => [f.name, f]));
  setAxes({ "ground.frequency": { from: 3, to: 7, steps: 21 }, "ground.amplitude": { from: 0.5, to: 2, steps: 4 } });
  // The assess tab: an assessment file's tower, building and name go into the form (the ground stays).
  assessView = new AssessView($("assess"), {
    scenario: () => scenario,
    apply(sections) {
      const { simulation, ...rest } = sections;
      for (const k of ["name", "tower", "building", "initial"]) delete scenario[k];
      Object.assign(scenario, rest);
      if (simulation) scenario.simulation = { ...scenario.simulation, ...simulation };
      removed = {};
      selectExample(null);
      buildForm();
      recompute();
    },
  });
  setupTabs([
    { tab: "tab-simulate", name: "simulate", panels: ["inputs", "results", "sweep"], view: null },
    { tab: "tab-assess", name: "assess", panels: ["inputs", "assess"], view: assessView },
    { tab: "tab-town", name: "town", panels: ["town"], view: new TownView($("town")) },
  ]);
  $("status").textContent = "Engine loaded.";
  if (loadFromUrl()) {
    buildForm();
    computeNow();
  } else {
    const first = Math.max(0, examples.findIndex((e) => e.path === "examples/tower-on-church.toml"));
    if (examples[first]) {
      selectExample(first);
      loadToml(examples[first].toml, examples[first].path);
    }
  }
}

main();
