// The tower rocking on the sliding church, to scale, driven by the history:
// the church moves by the slip u, the tower turns about its pivot corner
// (s b, 0) by θ (docs/src/model.md, "Points of the tower": Rot(θ) (x − s b, y)).
// The church's outline is schematic (the model knows only its mass); the
// tower's size, its rotation and the slip are true to scale.

export class Animation {
  constructor(canvas, slider, label, button) {
    Object.assign(this, { canvas, slider, label, button });
    this.index = 0;
    this.playing = false;
    slider.addEventListener("input", () => {
      this.index = Number(slider.value);
      this.draw();
    });
    button.addEventListener("click", () => (this.playing ? this.pause() : this.play()));
  }

  update(scenario, result) {
    const tower = scenario.tower || null;
    const b = tower && typeof tower.width === "number" ? tower.width / 2 : Math.max(0.5, (result.summary.R_m || 1) * Math.sin(result.summary.alpha_rad || 0.3));
    const h = tower && typeof tower.height === "number" ? tower.height : Math.max(1, (result.summary.R_m || 4) * Math.cos(result.summary.alpha_rad || 0.3) * 2);
    this.shape = { tower: !!tower, building: !!scenario.building, b, h };
    this.history = result.history;
    const n = this.history.t.length;
    this.slider.max = String(Math.max(0, n - 1));
    this.index = Math.min(this.index, n - 1);
    this.slider.value = String(this.index);
    this.draw();
  }

  play() {
    if (!this.history) return;
    this.playing = true;
    this.button.textContent = "❚❚ pause";
    const h = this.history;
    if (this.index >= h.t.length - 1) this.index = 0;
    let wall = performance.now();
    let t = h.t[this.index];
    const step = (now) => {
      if (!this.playing) return;
      t += (now - wall) / 1000;
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
  }

  draw() {
    const { canvas, history: hist, shape } = this;
    if (!hist || !shape) return;
    const ctx = canvas.getContext("2d");
    const i = this.index;
    const theta = hist.theta[i];
    const u = hist.slip[i];
    const { b, h } = shape;
    // The church: schematic, 4 tower widths long and half the tower's height.
    const church = shape.building ? { w: 8 * b, h: 0.5 * h } : { w: 0, h: 0 };
    const worldW = Math.max(church.w, 2 * b) + 2 * h;
    const worldH = church.h + h * 1.15;
    const scale = Math.min(canvas.width / worldW, (canvas.height - 30) / worldH);
    const X = (x) => canvas.width / 2 + x * scale;
    const Y = (y) => canvas.height - 20 - y * scale;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    // Ground.
    ctx.strokeStyle = "#555";
    ctx.beginPath();
    ctx.moveTo(0, Y(0));
    ctx.lineTo(canvas.width, Y(0));
    ctx.stroke();
    // Church, moved by the slip.
    const base = church.h;
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
      const s = theta > 0 ? 1 : theta < 0 ? -1 : 0;
      const c = Math.cos(theta);
      const sn = Math.sin(theta);
      const point = (x, y) => {
        const px = s * b + c * (x - s * b) + sn * y;
        const py = -sn * (x - s * b) + c * y;
        return [X(u + px), Y(base + py)];
      };
      ctx.beginPath();
      for (const [x, y] of [[-b, 0], [b, 0], [b, h], [-b, h]]) ctx.lineTo(...point(x, y));
      ctx.closePath();
      ctx.fillStyle = "#8c8c8c";
      ctx.fill();
      ctx.strokeStyle = "#333";
      ctx.stroke();
    }
    // Scale bar.
    const bar = Math.pow(10, Math.floor(Math.log10(worldW / 4)));
    ctx.fillStyle = "#333";
    ctx.fillRect(10, canvas.height - 8, bar * scale, 3);
    ctx.font = "11px sans-serif";
    ctx.fillText(`${bar} m`, 14 + bar * scale, canvas.height - 4);
    this.label.textContent = `t = ${hist.t[i].toFixed(3)} s   θ = ${theta.toExponential(3)} rad   slip = ${u.toExponential(3)} m   ${hist.regime[i]}`;
  }
}
