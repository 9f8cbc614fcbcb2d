// The sweep's heat map: max θ/α over the two swept keys (the first along x,
// the second along y; one row for a single key), overturned cases crossed,
// failed cases left blank, as in the command's sweep figure.

/** A colour for v in [0, 1] (viridis, 5 stops, linearly blended). */
function colour(v) {
  const stops = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  const x = Math.max(0, Math.min(1, v)) * (stops.length - 1);
  const k = Math.min(stops.length - 2, Math.floor(x));
  const f = x - k;
  const rgb = stops[k].map((a, j) => Math.round(a + f * (stops[k + 1][j] - a)));
  return `rgb(${rgb.join(",")})`;
}

export function drawHeatmap(canvas, columns, keys) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const xs = [...new Set(columns[keys[0]])];
  const ys = keys[1] ? [...new Set(columns[keys[1]])] : [null];
  const value = columns.max_theta_over_alpha;
  const over = columns.overturned;
  // Colours from 0 to 1 (overturning): a case above 1 is overturned and crossed.
  const left = 70;
  const bottom = 40;
  const right = 90;
  const w = (canvas.width - left - right) / xs.length;
  const h = (canvas.height - bottom - 20) / ys.length;
  for (let r = 0; r < value.length; r++) {
    const i = xs.indexOf(columns[keys[0]][r]);
    const j = keys[1] ? ys.indexOf(columns[keys[1]][r]) : 0;
    const x = left + i * w;
    const y = canvas.height - bottom - (j + 1) * h;
    if (value[r] === null) continue;
    ctx.fillStyle = colour(over[r] ? 1 : value[r]);
    // Whole pixels, each cell up to the next one's edge: no seams between cells.
    const [x0, y0] = [Math.floor(x), Math.floor(y)];
    ctx.fillRect(x0, y0, Math.floor(x + w) - x0, Math.floor(y + h) - y0);
    if (over[r]) {
      ctx.strokeStyle = "#c00";
      ctx.beginPath();
      ctx.moveTo(x + w * 0.2, y + h * 0.2);
      ctx.lineTo(x + w * 0.8, y + h * 0.8);
      ctx.moveTo(x + w * 0.8, y + h * 0.2);
      ctx.lineTo(x + w * 0.2, y + h * 0.8);
      ctx.stroke();
    }
  }
  ctx.fillStyle = "#222";
  ctx.font = "12px sans-serif";
  ctx.fillText(keys[0], left + (canvas.width - left - right) / 2 - 40, canvas.height - 6);
  const tick = (list, n) => list.filter((_, k) => k % Math.max(1, Math.ceil(list.length / n)) === 0);
  for (const v of tick(xs, 8)) ctx.fillText(String(+Number(v).toPrecision(4)), left + xs.indexOf(v) * w, canvas.height - bottom + 14);
  if (keys[1]) {
    ctx.save();
    ctx.translate(14, canvas.height / 2 + 40);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText(keys[1], 0, 0);
    ctx.restore();
    for (const v of tick(ys, 8)) ctx.fillText(String(+Number(v).toPrecision(4)), 24, canvas.height - bottom - (ys.indexOf(v) + 0.5) * h + 4);
  }
  // Colour bar.
  const bx = canvas.width - right + 20;
  for (let k = 0; k < 100; k++) {
    ctx.fillStyle = colour(1 - k / 100);
    ctx.fillRect(bx, 20 + (k * (canvas.height - bottom - 20)) / 100, 16, (canvas.height - bottom - 20) / 100 + 1);
  }
  ctx.fillStyle = "#222";
  ctx.fillText("max θ/α", bx - 10, 14);
  ctx.fillText("× overturned", bx - 30, canvas.height - bottom + 28);
  ctx.fillText("≥1", bx + 20, 30);
  ctx.fillText("0", bx + 20, canvas.height - bottom);
}
