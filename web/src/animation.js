// The tower rocking on the sliding church, driven by the history: the church
// moves by the slip u, the tower turns about its pivot corner (s b, 0) by θ
// (docs/src/model.md, "Points of the tower": Rot(θ) (x − s b, y)). The
// church's outline is schematic (the model knows only its mass); the tower's
// size is to scale, its rotation and the slip are to scale times the
// exaggeration factors written on the drawing. Dashed: the church where it
// started and the tower at rest on it. Under the slider, the timeline: the
// spans where the church slides shaded, the impacts as red ticks.
//
// Blocks stacked on the tower (a belfry) are drawn at their poses: each turns
// by its θ relative to the block below about its pivot corner, their
// positions sums of rotated vectors (docs/src/model.md, "A stack of blocks"),
// every rotation exaggerated by the same factor.

/** The exaggeration factors offered; "auto" picks one of them. */
export const FACTORS = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

/** The largest factor of FACTORS that keeps `peak × factor` within `target` (1 for a zero peak). */
export function autoFactor(peak, target) {
  if (!(peak > 0)) return 1;
  return FACTORS.filter((f) => peak * f <= target).pop() || 1;
}

/** R(φ) (x, y) with R(φ) = [[cos φ, sin φ], [−sin φ, cos φ]] (the model's rotation). */
function rotate(phi, x, y) {
  const c = Math.cos(phi);
  const s = Math.sin(phi);
  return [c * x + s * y, -s * x + c * y];
}

/**
 * The corners of each block of a stack at its pose, the tower first: blocks
 * of `widths` and `heights`, each turned by `thetas[k]` relative to the one
 * below about the corner sgn θ of its base, on a base at `shift`. Block k's
 * base centre is C_k = C_{k−1} + R(φ_{k−1}) (s_k B_k/2, H_{k−1}) + R(φ_k) (−s_k B_k/2, 0),
 * with C_0 = (shift, 0), H_0 = 0 and φ_k = θ_1 + … + θ_k; its corners
 * C_k + R(φ_k) (±B_k/2, 0 or H_k).
 */
export function stackCorners(shift, widths, heights, thetas) {
  const out = [];
  let [cx, cy] = [shift, 0];
  let phi = 0;
  let below = 0;
  widths.forEach((width, k) => {
    const half = width / 2;
    const side = Math.sign(thetas[k]);
    const [ax, ay] = rotate(phi, side * half, below);
    phi += thetas[k];
    const [bx, by] = rotate(phi, -side * half, 0);
    cx += ax + bx;
    cy += ay + by;
    out.push(
      [[-half, 0], [half, 0], [half, heights[k]], [-half, heights[k]]].map(([x, y]) => {
        const [rx, ry] = rotate(phi, x, y);
        return [cx + rx, cy + ry];
      }),
    );
    below = heights[k];
  });
  return out;
}

export class Animation {
  /** `controls`: { slider, label, button, timeline, theta, slip, speed } (elements). */
  constructor(canvas, controls) {
    Object.assign(this, { canvas, ...controls });
    this.index = 0;
    this.playing = false;
    this.slider.addEventListener("input", () => {
      this.index = Number(this.slider.value);
      this.draw();
    });
    this.button.addEventListener("click", () => (this.playing ? this.pause() : this.play()));
    for (const select of [this.theta, this.slip]) {
      select.replaceChildren(new Option("auto", "auto"), ...FACTORS.map((f) => new Option(`${f}×`, String(f))));
      select.addEventListener("change", () => this.draw());
    }
    for (const s of [0.25, 0.5, 1, 2, 4]) this.speed.append(new Option(`${s}×`, String(s), s === 1, s === 1));
    this.timeline.addEventListener("click", (e) => {
      const box = this.timeline.getBoundingClientRect();
      this.seek(((e.clientX - box.left) / box.width) * this.end());
    });
  }

  update(scenario, result) {
    const tower = scenario.tower || null;
    const s = result.summary;
    const b = tower && typeof tower.width === "number" ? tower.width / 2 : Math.max(0.5, (s.R_m || 1) * Math.sin(s.alpha_rad || 0.3));
    const h = tower && typeof tower.height === "number" ? tower.height : Math.max(1, (s.R_m || 4) * Math.cos(s.alpha_rad || 0.3) * 2);
    // The blocks on the tower as the engine built them (the check's `blocks`).
    const blocks = (tower && result.derived?.blocks) || [];
    this.shape = { tower: !!tower, building: !!scenario.building, b, h, blocks };
    this.alpha = s.alpha_rad;
    this.history = result.history;
    this.regimeNames = result.regimeNames;
    this.events = result.events;
    this.slips = result.slips;
    // auto: a peak rotation drawn as about 15°, a peak slip as a quarter of the church's length (8 b).
    const peak = Math.max(s.max_abs_theta_rad || 0, ...blocks.map((k) => s[`${k.name}_max_abs_theta_rad`] || 0));
    this.auto = { theta: autoFactor(peak, (15 * Math.PI) / 180), slip: autoFactor(s.max_abs_slip_m, 2 * b) };
    for (const [key, select] of [["theta", this.theta], ["slip", this.slip]]) select.options[0].text = `auto (${this.auto[key]}×)`;
    const n = this.history.t.length;
    this.slider.max = String(Math.max(0, n - 1));
    this.index = Math.min(this.index, n - 1);
    this.slider.value = String(this.index);
    this.canvas.setAttribute(
      "aria-label",
      `The tower on the church, animated: peak θ/α ${fmt(s.max_theta_over_alpha)}, peak slip ${fmt(s.max_abs_slip_m)} m, ` +
        `${s.impacts ?? 0} impacts${s.overturned ? `, overturned at ${fmt(s.overturn_time_s)} s` : ""}.`,
    );
    this.draw();
  }

  /** The exaggeration factor in use for "theta" or "slip". */
  factor(key) {
    const v = this[key].value;
    return v === "auto" ? this.auto?.[key] || 1 : Number(v);
  }

  end() {
    const t = this.history?.t;
    return t ? t[t.length - 1] : 0;
  }

  /** Shows the last row at or before time `t`. */
  seek(t) {
    const times = this.history?.t;
    if (!times) return;
    let lo = 0;
    let hi = times.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (times[mid] <= t) lo = mid;
      else hi = mid - 1;
    }
    this.index = lo;
    this.slider.value = String(lo);
    this.draw();
  }

  play() {
    if (!this.history) return;
    this.playing = true;
    this.button.textContent = "❚❚ pause";
    this.button.setAttribute("aria-label", "pause the animation");
    const h = this.history;
    if (this.index >= h.t.length - 1) this.index = 0;
    let wall = performance.now();
    let t = h.t[this.index];
    const step = (now) => {
      if (!this.playing) return;
      t += ((now - wall) / 1000) * Number(this.speed.value);
      wall = now;
      while (this.index < h.t.length - 1 && h.t[this.index + 1] <= t) this.index++;
      this.slider.value = String(this.index);
      this.draw();
      if (this.index >= h.t.length - 1) return this.pause();
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  pause() {
    this.playing = false;
    this.button.textContent = "▶ play";
    this.button.setAttribute("aria-label", "play the animation");
  }

  draw() {
    const { canvas, history: hist, shape } = this;
    if (!hist || !shape) return;
    const ctx = canvas.getContext("2d");
    const i = this.index;
    const fTheta = this.factor("theta");
    const fSlip = this.factor("slip");
    // Past a quarter turn the drawing would fold over: the drawn angle stops at 90°.
    const drawn = (x) => Math.max(-Math.PI / 2, Math.min(Math.PI / 2, x * fTheta));
    const theta = drawn(hist.theta[i]);
    const u = hist.slip[i] * fSlip;
    const { b, h, blocks } = shape;
    const widths = [2 * b, ...blocks.map((k) => k.width_m)];
    const heights = [h, ...blocks.map((k) => k.height_m)];
    const thetas = [theta, ...blocks.map((k) => drawn(hist[`${k.name}_theta`][i]))];
    const total = heights.reduce((a, x) => a + x, 0);
    // The church: schematic, 4 tower widths long and half the tower's height.
    const church = shape.building ? { w: 8 * b, h: 0.5 * h } : { w: 0, h: 0 };
    const worldW = Math.max(church.w, 2 * b) + 2 * total;
    const worldH = church.h + total * 1.15;
    const scale = Math.min(canvas.width / worldW, (canvas.height - 46) / worldH);
    const X = (x) => canvas.width / 2 + x * scale;
    const Y = (y) => canvas.height - 20 - y * scale;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    // Ground.
    ctx.strokeStyle = "#555";
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(0, Y(0));
    ctx.lineTo(canvas.width, Y(0));
    ctx.stroke();
    const base = church.h;
    const churchPath = (shift) => {
      ctx.beginPath();
      ctx.moveTo(X(shift - church.w / 2), Y(0));
      ctx.lineTo(X(shift - church.w / 2), Y(church.h));
      ctx.lineTo(X(shift), Y(church.h * 1.35));
      ctx.lineTo(X(shift + church.w / 2), Y(church.h));
      ctx.lineTo(X(shift + church.w / 2), Y(0));
    };
    // The tower and its blocks, each a closed path of its corners.
    const stackPaths = (shift, angles) =>
      stackCorners(shift, widths, heights, angles).map((corners) => {
        const path = new Path2D();
        for (const [x, y] of corners) path.lineTo(X(x), Y(base + y));
        path.closePath();
        return path;
      });
    if (shape.building) {
      ctx.fillStyle = "#d9c8a9";
      ctx.fillRect(X(u - church.w / 2), Y(church.h), church.w * scale, church.h * scale);
      ctx.beginPath();
      ctx.moveTo(X(u - church.w / 2), Y(church.h));
      ctx.lineTo(X(u), Y(church.h * 1.35));
      ctx.lineTo(X(u + church.w / 2), Y(church.h));
      ctx.closePath();
      ctx.fillStyle = "#b5634b";
      ctx.fill();
    }
    if (shape.tower) {
      stackPaths(u, thetas).forEach((path, k) => {
        ctx.fillStyle = k ? "#a89a86" : "#8c8c8c";
        ctx.fill(path);
        ctx.strokeStyle = "#333";
        ctx.stroke(path);
      });
    }
    // The ghosts: the church where it started, the tower at rest on it.
    ctx.strokeStyle = "rgba(30, 60, 140, 0.8)";
    ctx.setLineDash([5, 4]);
    if (shape.building) {
      churchPath(0);
      ctx.stroke();
    }
    if (shape.tower) for (const path of stackPaths(0, thetas.map(() => 0))) ctx.stroke(path);
    ctx.setLineDash([]);
    // Scale bar (true lengths) and the factors.
    const bar = Math.pow(10, Math.floor(Math.log10(worldW / 4)));
    ctx.fillStyle = "#333";
    ctx.fillRect(10, canvas.height - 8, bar * scale, 3);
    ctx.font = "12px sans-serif";
    ctx.fillText(`${bar} m`, 14 + bar * scale, canvas.height - 4);
    ctx.fillText(`rotation ×${fTheta}, slip ×${fSlip}${fTheta > 1 || fSlip > 1 ? " (exaggerated)" : " (true scale)"}; dashed: at rest`, 10, 16);
    // What the drawing shows, for tests and assistive technology.
    canvas.dataset.pxPerM = String(scale);
    canvas.dataset.churchShiftPx = String(u * scale);
    canvas.dataset.drawnThetaRad = String(theta);
    canvas.dataset.drawnBlockThetaRad = JSON.stringify(thetas.slice(1));
    const regime = this.regimeNames[hist.regime[i]];
    const onTop = blocks.map((k) => `   ${k.name} θ/α = ${fmt(hist[`${k.name}_theta`][i] / k.alpha_rad)}`).join("");
    this.label.textContent = `t = ${hist.t[i].toFixed(3)} s   θ/α = ${fmt(hist.theta[i] / (this.alpha || 1))}${onTop}   θ = ${hist.theta[i].toExponential(3)} rad   slip = ${hist.slip[i].toExponential(3)} m   ${regime}`;
    this.slider.setAttribute("aria-valuetext", `t = ${hist.t[i].toFixed(3)} s`);
    this.drawTimeline();
  }

  drawTimeline() {
    const c = this.timeline;
    const ctx = c.getContext("2d");
    const end = this.end() || 1;
    const x = (t) => (t / end) * c.width;
    ctx.clearRect(0, 0, c.width, c.height);
    ctx.fillStyle = "#eee";
    ctx.fillRect(0, 0, c.width, c.height);
    ctx.fillStyle = "rgba(230, 140, 20, 0.6)";
    for (const [a, b] of this.slips || []) ctx.fillRect(x(a), 0, Math.max(1, x(b) - x(a)), c.height);
    ctx.strokeStyle = "#c00";
    ctx.beginPath();
    for (const e of this.events || []) {
      // The tower's and each block's (`belfry_impact`).
      if (!/(^|_)(impact|overturn)$/.test(e.kind)) continue;
      const px = Math.round(x(e.t)) + 0.5;
      ctx.moveTo(px, 0);
      ctx.lineTo(px, c.height);
    }
    ctx.stroke();
    ctx.fillStyle = "#1f4e99";
    ctx.fillRect(x(this.history.t[this.index]) - 1, 0, 2, c.height);
  }
}

function fmt(v) {
  return typeof v === "number" ? String(Number(v.toPrecision(3))) : "—";
}
