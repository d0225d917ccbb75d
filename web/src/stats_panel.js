// The per-frame statistics of the panel: small line plots of the detection stages and
// times (from steps.jsonl summed per frame), and a table of every field at the frame.

const PLOTS = [
  { title: 'candidate triangle pairs', series: ['detection.candidate_triangle_pairs'] },
  {
    title: 'VF pairs: generated \u2192 boxes \u2192 filter \u2192 CCD \u2192 colliding (log)', log: true,
    series: ['detection.vf_generated', 'detection.vf_after_boxes', 'detection.vf_after_filter',
      'detection.vf_tested', 'detection.vf_colliding'],
  },
  {
    title: 'EE pairs: generated \u2192 boxes \u2192 filter \u2192 CCD \u2192 colliding (log)', log: true,
    series: ['detection.ee_generated', 'detection.ee_after_boxes', 'detection.ee_after_filter',
      'detection.ee_tested', 'detection.ee_colliding'],
  },
  {
    title: 'time per frame (ms)',
    series: ['ms.step', 'ms.forces_solve', 'ms.detection', 'ms.response', 'detection.total_ms'],
  },
];
const LINE_COLORS = ['#7fb2ff', '#ffd000', '#ff8c00', '#ff4d4d', '#ff66ff'];

function formatNumber(value) {
  if (value === null || value === undefined) return '\u2013';
  return Number.isInteger(value) ? String(value) : value.toFixed(3);
}

export class StatsPanel {
  constructor(plotsElement, tableElement, stats, frames) {
    this.series = (stats && stats.series) || {};
    this.frames = frames;
    this.table = tableElement;
    this.plots = [];
    if (frames < 3) {
      plotsElement.textContent = 'one step: see the table below';
      return;
    }
    for (const spec of PLOTS) {
      const names = spec.series.filter((name) => name in this.series);
      if (names.length === 0) continue;
      const title = document.createElement('div');
      title.textContent = spec.title;
      const canvas = document.createElement('canvas');
      canvas.className = 'plot';
      canvas.width = 250;
      canvas.height = 70;
      canvas.title = names.join(', ');
      const legend = document.createElement('div');
      names.forEach((name, i) => {
        const swatch = document.createElement('span');
        swatch.className = 'swatch';
        swatch.style.background = LINE_COLORS[i];
        legend.append(swatch, name.replace(/^(detection|ms)\./, '') + ' ');
      });
      plotsElement.append(title, canvas, legend);
      this.plots.push({ canvas, names, log: !!spec.log });
    }
    if (this.plots.length === 0) plotsElement.textContent = 'no steps.jsonl in this output';
  }

  show(frame) {
    for (const plot of this.plots) this.draw(plot, frame);
    const rows = Object.keys(this.series).sort().map((name) => {
      const row = document.createElement('tr');
      const label = document.createElement('td');
      const value = document.createElement('td');
      label.textContent = name;
      value.textContent = formatNumber(this.series[name][frame]);
      row.append(label, value);
      return row;
    });
    this.table.replaceChildren(...rows);
  }

  draw({ canvas, names, log }, frame) {
    const context = canvas.getContext('2d');
    const { width, height } = canvas;
    const scale = (v) => (log ? Math.log10(1 + Math.max(0, v)) : v);
    let top = 0;
    for (const name of names) {
      for (const v of this.series[name]) if (v !== null) top = Math.max(top, scale(v));
    }
    top = top > 0 ? top : 1;
    const x = (k) => 2 + (k / Math.max(1, this.frames - 1)) * (width - 4);
    const y = (v) => height - 2 - (scale(v) / top) * (height - 12);
    context.clearRect(0, 0, width, height);
    context.fillStyle = 'rgba(255,255,255,0.05)';
    context.fillRect(0, 0, width, height);
    names.forEach((name, i) => {
      context.strokeStyle = LINE_COLORS[i];
      context.beginPath();
      let drawing = false;
      this.series[name].forEach((v, k) => {
        if (v === null) {
          drawing = false;
          return;
        }
        if (drawing) context.lineTo(x(k), y(v));
        else context.moveTo(x(k), y(v));
        drawing = true;
      });
      context.stroke();
    });
    context.strokeStyle = '#ffffff';
    context.beginPath();
    context.moveTo(x(frame), 0);
    context.lineTo(x(frame), height);
    context.stroke();
    context.fillStyle = '#ccd';
    context.fillText(log ? `10^${top.toFixed(1)}` : formatNumber(top), 4, 10);
  }
}
