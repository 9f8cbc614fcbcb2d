// The sweep's heat map: max θ/α over the two swept keys (the first along x,
// the second along y; one row for a single key), the colours spread over the
// data's own range (linear, or logarithmic), overturned cases crossed,
// failed cases hatched grey, as in the command's sweep figure. Hovering a
// cell shows its values.

/** A colour for v in [0, 1] (viridis, 5 stops, linearly blended). */
export function colour(v) {
  const stops = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  const x = Math.max(0, Math.min(1, v)) * (stops.length - 1);
  const k = Math.min(stops.length - 2, Math.floor(x));
  const f = x - k;
  const rgb = stops[k].map((a, j) => Math.round(a + f * (stops[k + 1][j] - a)));
  return `rgb(${rgb.join(",")})`;
}

/**
 * The colour scale of the values: [lo, hi] of the finite values of the cases
 * that did not overturn (those of all cases if every one did), and the map
 * of a value to [0, 1], linear or, with `log`, logarithmic over the positive
 * values (a zero is put at the bottom).
 */
export function colourScale(values, overturned, log) {
  const pick = (keep) => values.filter((v, r) => v !== null && Number.isFinite(v) && keep(r));
  let data = pick((r) => !overturned[r]);
  if (data.length === 0) data = pick(() => true);
  if (log) data = data.filter((v) => v > 0);
  if (data.length === 0) return { lo: 0, hi: 1, log: false, at: () => 0 };
  const lo = Math.min(...data);
  const hi = Math.max(...data);
  if (log) {
    const [a, b] = [Math.log10(lo), Math.log10(hi)];
    return { lo, hi, log, at: (v) => (v <= 0 ? 0 : b > a ? (Math.log10(v) - a) / (b - a) : 0.5) };
  }
  return { lo, hi, log, at: (v) => (hi > lo ? (v - lo) / (hi - lo) : 0.5) };
}

const tickText = (v) => String(+Number(v).toPrecision(4));

/**
 * Draws the map on `canvas` from the sweep.csv columns. `keys`: the swept
 * keys; `labels`: their axis names with units; `log`: a logarithmic scale.
 * Leaves on the canvas what it shows (data-colour-min/max, a text
 * alternative) and returns a function that names the case under a point.
 */
export function drawHeatmap(canvas, columns, keys, labels, log = false) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const xs = [...new Set(columns[keys[0]])];
  const ys = keys[1] ? [...new Set(columns[keys[1]])] : [null];
  const value = columns.max_theta_over_alpha;
  const over = columns.overturned;
  const scale = colourScale(value, over, log);
  const left = 80;
  const bottom = 44;
  const right = 110;
  const top = 24;
  const plotW = canvas.width - left - right;
  const plotH = canvas.height - bottom - top;
  // Cell edges on whole pixels, each cell up to the next one's edge: no seams.
  const xEdge = (i) => Math.round(left + (i * plotW) / xs.length);
  const yEdge = (j) => Math.round(canvas.height - bottom - (j * plotH) / ys.length);
  const xIndex = new Map(xs.map((v, i) => [v, i]));
  const yIndex = new Map(ys.map((v, j) => [v, j]));
  // The case of each cell (-1: none), for the hover.
  const grid = new Int32Array(xs.length * ys.length).fill(-1);
  for (let r = 0; r < value.length; r++) {
    const i = xIndex.get(columns[keys[0]][r]);
    const j = keys[1] ? yIndex.get(columns[keys[1]][r]) : 0;
    grid[j * xs.length + i] = r;
    const [x0, x1, y0, y1] = [xEdge(i), xEdge(i + 1), yEdge(j + 1), yEdge(j)];
    if (value[r] === null) {
      // A failed case: grey, hatched.
      ctx.fillStyle = "#bbb";
      ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
      ctx.strokeStyle = "#888";
      ctx.beginPath();
      ctx.moveTo(x0, y1);
      ctx.lineTo(x1, y0);
      ctx.stroke();
      continue;
    }
    ctx.fillStyle = colour(over[r] ? 1 : scale.at(value[r]));
    ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
    if (over[r]) {
      const [w, h] = [x1 - x0, y1 - y0];
      ctx.strokeStyle = "#c00";
      ctx.beginPath();
      ctx.moveTo(x0 + w * 0.2, y0 + h * 0.2);
      ctx.lineTo(x0 + w * 0.8, y0 + h * 0.8);
      ctx.moveTo(x0 + w * 0.8, y0 + h * 0.2);
      ctx.lineTo(x0 + w * 0.2, y0 + h * 0.8);
      ctx.stroke();
    }
  }
  ctx.fillStyle = "#222";
  ctx.font = "12px sans-serif";
  ctx.textAlign = "center";
  ctx.fillText(labels[0], left + plotW / 2, canvas.height - 6);
  const tick = (list, n) => list.filter((_, k) => k % Math.max(1, Math.ceil(list.length / n)) === 0);
  // About one x tick per 50 px, so that their texts never touch.
  for (const v of tick(xs, Math.max(2, Math.min(8, Math.floor(plotW / 50))))) ctx.fillText(tickText(v), (xEdge(xs.indexOf(v)) + xEdge(xs.indexOf(v) + 1)) / 2, canvas.height - bottom + 14);
  ctx.textAlign = "right";
  if (keys[1]) {
    ctx.save();
    ctx.translate(14, top + plotH / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textAlign = "center";
    ctx.fillText(labels[1], 0, 0);
    ctx.restore();
    for (const v of tick(ys, 8)) ctx.fillText(tickText(v), left - 6, (yEdge(ys.indexOf(v)) + yEdge(ys.indexOf(v) + 1)) / 2 + 4);
  }
  // Colour bar: the data's range.
  const bx = canvas.width - right + 24;
  for (let k = 0; k < 100; k++) {
    ctx.fillStyle = colour(1 - k / 100);
    ctx.fillRect(bx, top + (k * plotH) / 100, 16, plotH / 100 + 1);
  }
  ctx.textAlign = "left";
  ctx.fillStyle = "#222";
  ctx.fillText(`max θ/α${scale.log ? " (log)" : ""}`, bx - 20, 14);
  ctx.fillText(tickText(scale.hi), bx + 20, top + 10);
  ctx.fillText(tickText(scale.lo), bx + 20, top + plotH);
  ctx.fillText("× overturned", bx - 24, canvas.height - bottom + 20);
  ctx.fillText("grey: failed", bx - 24, canvas.height - bottom + 34);
  canvas.dataset.colourMin = String(scale.lo);
  canvas.dataset.colourMax = String(scale.hi);
  const overturned = over.filter(Boolean).length;
  const failed = value.filter((v) => v === null).length;
  canvas.setAttribute(
    "aria-label",
    `Heat map of max θ/α over ${labels.join(" and ")}: ${value.length} cases, from ${tickText(scale.lo)} to ${tickText(scale.hi)}` +
      `${overturned ? `, ${overturned} overturned` : ""}${failed ? `, ${failed} failed` : ""}.`,
  );
  // The case under a point of the canvas (in its own pixels), or null.
  return (px, py) => {
    const i = Math.floor(((px - left) / plotW) * xs.length);
    const j = Math.floor(((canvas.height - bottom - py) / plotH) * ys.length);
    if (i < 0 || i >= xs.length || j < 0 || j >= ys.length) return null;
    const r = grid[j * xs.length + i];
    if (r < 0) return null;
    const where = keys.map((k, n) => `${labels[n]} = ${tickText(columns[k][r])}`).join(", ");
    const what = value[r] === null ? `failed: ${columns.error?.[r] || "no value"}` : `max θ/α = ${tickText(value[r])}${over[r] ? " (overturned)" : ""}`;
    return `${where}: ${what}`;
  };
}
