// Scrolling time plots on a canvas: a few series over the last `span` seconds of robot time.
'use strict';
class Plot {
  // title: text; series: [{ name, color }]; span: s of history shown
  constructor(canvas, title, series, span = 10) {
    this.c = canvas; this.g = canvas.getContext('2d');
    this.title = title; this.series = series; this.span = span;
    this.t = []; this.v = series.map(() => []);
  }
  // Adds a sample at robot time t (a time going back, e.g. a restarted sim, starts afresh).
  add(t, values) {
    if (this.t.length && t < this.t[this.t.length - 1]) this.clear();
    this.t.push(t);
    values.forEach((x, i) => this.v[i].push(x));
    while (this.t.length > 2 && this.t[0] < t - this.span) { this.t.shift(); this.v.forEach(a => a.shift()); }
  }
  clear() { this.t = []; this.v = this.series.map(() => []); }
  draw() {
    const g = this.g, W = this.c.width, H = this.c.height, L = 40, R = 6, T = 24, B = 14;
    g.fillStyle = '#181c22'; g.fillRect(0, 0, W, H);
    g.font = '11px system-ui, sans-serif';
    g.fillStyle = '#dfe3e8'; g.fillText(this.title, 4, 12);
    let x = 4 + g.measureText(this.title).width + 10;
    this.series.forEach(s => { g.fillStyle = s.color; g.fillText(s.name, x, 12); x += g.measureText(s.name).width + 8; });
    if (this.t.length < 2) return;
    let lo = Infinity, hi = -Infinity;
    this.v.forEach(a => a.forEach(y => { if (y !== null && isFinite(y)) { lo = Math.min(lo, y); hi = Math.max(hi, y); } }));
    if (!isFinite(lo)) return;
    if (hi - lo < 1e-6) { lo -= 0.5; hi += 0.5; }
    const pad = (hi - lo) * 0.08; lo -= pad; hi += pad;
    const t1 = this.t[this.t.length - 1], t0 = t1 - this.span;
    const px = t => L + (t - t0) / this.span * (W - L - R), py = y => T + (hi - y) / (hi - lo) * (H - T - B);
    g.strokeStyle = '#2c333c'; g.fillStyle = '#8a939e'; g.lineWidth = 1;
    for (let k = 0; k <= 2; k++) {
      const y = lo + (hi - lo) * k / 2, yy = Math.round(py(y)) + 0.5;
      g.beginPath(); g.moveTo(L, yy); g.lineTo(W - R, yy); g.stroke();
      g.fillText(y.toPrecision(3), 2, yy + 4);
    }
    g.fillText(`${this.span} s`, W - R - 24, H - 3);
    this.v.forEach((a, i) => {
      g.strokeStyle = this.series[i].color; g.lineWidth = 1.5; g.beginPath();
      let pen = false;
      a.forEach((y, j) => {
        if (y === null || !isFinite(y)) { pen = false; return; }
        if (pen) g.lineTo(px(this.t[j]), py(y)); else g.moveTo(px(this.t[j]), py(y));
        pen = true;
      });
      g.stroke();
    });
  }
}
