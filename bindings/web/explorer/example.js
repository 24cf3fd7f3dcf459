// example.html: the curve factories on a canvas, with pixel scales like d3's.
import { load, curveTrig, curveTrigPositive, curveTrigBetween } from '../trigspline.js';

await load();
const data = [[0, 2], [1, 1.9], [2, 0.05], [3, 0.02], [4, 1.2], [5, 2.1], [6, 0.3], [7, 0.01], [8, 1.5]];
const canvas = document.getElementById('c'), ctx = canvas.getContext('2d');
// scales: data -> pixels, with invert (what d3.scaleLinear provides)
const linear = (d0, d1, r0, r1) => Object.assign((v) => r0 + ((v - d0) / (d1 - d0)) * (r1 - r0),
  { invert: (p) => d0 + ((p - r0) / (r1 - r0)) * (d1 - d0) });
const x = linear(-0.3, 8.3, 0, canvas.width), y = linear(-0.4, 2.4, canvas.height, 0);

function draw(factory, color, dash = []) {
  ctx.setLineDash(dash);
  ctx.beginPath();
  const curve = factory(ctx);
  curve.lineStart();
  for (const [a, b] of data) curve.point(x(a), y(b));
  curve.lineEnd();
  ctx.strokeStyle = color;
  ctx.lineWidth = 2;
  ctx.stroke();
}
ctx.fillStyle = 'rgba(208,2,27,0.08)';
ctx.fillRect(0, y(0), canvas.width, canvas.height - y(0)); // below 0: forbidden for both
ctx.fillRect(0, 0, canvas.width, y(2.2)); // above 2.2: forbidden for curveTrigBetween(0, 2.2)
draw((c) => ({ lineStart() {}, lineEnd() {}, point(px, py) { c.lineTo(px, py); } }), '#bbb');
draw(curveTrig.scales(x, y), '#e69500');
draw(curveTrigPositive.scales(x, y), '#1f5fbf');
draw(curveTrigBetween(0, 2.2).scales(x, y), '#2e8b57', [7, 5]);
ctx.setLineDash([]);
ctx.fillStyle = '#111';
for (const [a, b] of data) { ctx.beginPath(); ctx.arc(x(a), y(b), 3.5, 0, 2 * Math.PI); ctx.fill(); }
document.getElementById('note').textContent = 'drawn';
document.body.dataset.ready = '1';
