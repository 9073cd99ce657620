// The field seen from above: lines from the config, each robot's true pose (sim), believed pose and
// particles, the ball's truth, sighting and filtered estimate, goal posts seen.
// Geometry (the tests rely on it): the field's centre at the canvas's centre, x to the right, y up,
// `scale` canvas pixels per metre.
'use strict';
class FieldView {
  constructor(canvas, f) {
    this.c = canvas; this.g = canvas.getContext('2d'); this.f = f;
    const border = f.border ?? 0.7;
    this.scale = Math.min(canvas.width / (f.length + 2 * border), canvas.height / (f.width + 2 * border));
  }
  px(x, y) { return [this.c.width / 2 + x * this.scale, this.c.height / 2 - y * this.scale]; }
  geometry() { return { scale: this.scale, cx: this.c.width / 2, cy: this.c.height / 2 }; }

  lines() {
    const g = this.g, f = this.f, s = this.scale, L = f.length / 2, W = f.width / 2;
    g.fillStyle = '#2f7d32'; g.fillRect(0, 0, this.c.width, this.c.height);
    g.strokeStyle = '#f4f4f4'; g.lineWidth = Math.max(1.5, (f.line_width ?? 0.05) * s);
    const rect = (x0, y0, x1, y1) => {
      const [a, b] = this.px(x0, y1), [c, d] = this.px(x1, y0);
      g.strokeRect(a, b, c - a, d - b);
    };
    rect(-L, -W, L, W);
    g.beginPath(); g.moveTo(...this.px(0, -W)); g.lineTo(...this.px(0, W)); g.stroke();
    g.beginPath(); g.arc(...this.px(0, 0), (f.centre_circle_diameter ?? 1.5) / 2 * s, 0, 2 * Math.PI); g.stroke();
    for (const side of [-1, 1]) {
      const ga = f.goal_area_length ?? 1, gw = (f.goal_area_width ?? 3) / 2;
      const pa = f.penalty_area_length ?? 2, pw = (f.penalty_area_width ?? 5) / 2;
      rect(Math.min(side * L, side * (L - ga)), -gw, Math.max(side * L, side * (L - ga)), gw);
      rect(Math.min(side * L, side * (L - pa)), -pw, Math.max(side * L, side * (L - pa)), pw);
      const [mx, my] = this.px(side * (L - (f.penalty_mark_distance ?? 1.5)), 0);
      g.fillStyle = '#f4f4f4'; g.fillRect(mx - 3, my - 1, 6, 2); g.fillRect(mx - 1, my - 3, 2, 6);
      // the goal: posts and net behind the line
      const hw = (f.goal_width ?? 2.6) / 2, d = 0.6;
      g.fillStyle = 'rgba(255,255,255,0.18)';
      const [a, b] = this.px(side > 0 ? L : -L - d, hw), [c, e] = this.px(side > 0 ? L + d : -L, -hw);
      g.fillRect(a, b, c - a, e - b);
      g.fillStyle = '#ffffff';
      for (const y of [-hw, hw]) { const [x0, y0] = this.px(side * L, y); g.beginPath(); g.arc(x0, y0, 4, 0, 2 * Math.PI); g.fill(); }
    }
  }

  // A robot: a disc with a heading line; filled (truth) or a ring (belief).
  pose(x, y, yaw, color, filled) {
    const g = this.g, [u, v] = this.px(x, y), r = 0.13 * this.scale;
    g.lineWidth = 3;
    if (filled) {
      g.fillStyle = color; g.beginPath(); g.arc(u, v, r, 0, 2 * Math.PI); g.fill();
      g.strokeStyle = '#000'; g.lineWidth = 2;
    } else {
      g.strokeStyle = color; g.setLineDash([5, 3]);
      g.beginPath(); g.arc(u, v, r + 4, 0, 2 * Math.PI); g.stroke(); g.setLineDash([]);
    }
    g.beginPath(); g.moveTo(u, v); g.lineTo(u + Math.cos(yaw) * (r + 10), v - Math.sin(yaw) * (r + 10)); g.stroke();
  }

  ball(x, y, kind) {
    const g = this.g, [u, v] = this.px(x, y), r = Math.max(4, 0.07 * this.scale);
    g.lineWidth = 2; g.strokeStyle = '#ff8c1a'; g.fillStyle = '#ff8c1a';
    if (kind === 'truth') { g.beginPath(); g.arc(u, v, r, 0, 2 * Math.PI); g.fill(); }
    else if (kind === 'seen') { g.beginPath(); g.arc(u, v, r + 3, 0, 2 * Math.PI); g.stroke(); }
    else { g.beginPath(); g.moveTo(u - r, v - r); g.lineTo(u + r, v + r); g.moveTo(u + r, v - r); g.lineTo(u - r, v + r); g.stroke(); }
  }

  // robots: [{ id, color, light, truth, belief, particles, ballTruth, ballSeen, ballFiltered, posts }]
  draw(robots) {
    this.lines();
    const g = this.g;
    for (const r of robots) {
      if (r.particles) {
        g.fillStyle = r.light; g.globalAlpha = 0.55;
        for (let i = 0; i + 1 < r.particles.length; i += 3) {
          const [u, v] = this.px(r.particles[i], r.particles[i + 1]);
          g.fillRect(u - 1.5, v - 1.5, 3, 3);
        }
        g.globalAlpha = 1;
      }
    }
    for (const r of robots) {
      if (r.ballTruth) this.ball(r.ballTruth[0], r.ballTruth[1], 'truth');
    }
    for (const r of robots) {
      if (r.truth) this.pose(r.truth[0], r.truth[1], r.truth[2], r.color, true);
      if (r.belief) this.pose(r.belief[0], r.belief[1], r.belief[2], r.light, false);
      if (r.ballSeen) this.ball(r.ballSeen[0], r.ballSeen[1], 'seen');
      if (r.ballFiltered) this.ball(r.ballFiltered[0], r.ballFiltered[1], 'filtered');
      for (const p of r.posts || []) {
        const [u, v] = this.px(p[0], p[1]);
        g.strokeStyle = r.light; g.lineWidth = 2; g.strokeRect(u - 5, v - 5, 10, 10);
      }
      const at = r.truth || r.belief;
      if (at) {
        const [u, v] = this.px(at[0], at[1]);
        g.font = 'bold 12px system-ui, sans-serif'; g.fillStyle = '#fff';
        const label = String(r.id), w = g.measureText(label).width;   // kept inside the canvas
        g.fillText(label, Math.min(u + 14, this.c.width - w - 4), Math.max(14, v - 12));
      }
    }
  }
}
