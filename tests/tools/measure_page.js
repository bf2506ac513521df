// Injected by check_reports.sh layout into a copy of a page, run by headless
// Chromium (--dump-dom): what runs off. Prints, in a pre element of id
// "measured", one line each:
//   size W H           the document's scroll width and height (px)
//   off TAG TEXT       an element whose box ends right of the body's
//   svg ID clip TEXT   a text of a plot not 2 px inside its plot's box
//   svg ID frame TEXT  a text inside a plotting area's frame not 2 px clear of its sides
(function () {
  const lines = [];
  const root = document.documentElement;
  lines.push('size ' + root.scrollWidth + ' ' + root.scrollHeight);
  const body = document.body.getBoundingClientRect();
  const snippet = (e) => (e.textContent || '').replace(/\s+/g, ' ').trim().slice(0, 70);
  for (const e of document.body.querySelectorAll('*')) {
    if (e.closest('svg') && e.tagName.toLowerCase() !== 'svg') continue;
    const r = e.getBoundingClientRect();
    if (r.width > 0 && r.right > body.right + 0.5) lines.push('off ' + e.tagName.toLowerCase() + ' ' + snippet(e));
  }
  for (const svg of document.querySelectorAll('svg')) {
    const box = svg.getBoundingClientRect();
    const margin = 2 * box.width / svg.viewBox.baseVal.width;  // 2 px of the plot's own
    // The plotting areas' frames: a text inside one (an off-scale value)
    // keeps clear of its sides too.
    const frames = [...svg.querySelectorAll('rect[fill="none"][stroke="#000000"]')].map((f) => f.getBoundingClientRect());
    for (const t of svg.querySelectorAll('text')) {
      const r = t.getBoundingClientRect();
      if (r.left < box.left + margin || r.right > box.right - margin || r.top < box.top || r.bottom > box.bottom) {
        lines.push('svg ' + svg.id + ' clip ' + snippet(t));
      }
      const x = (r.left + r.right) / 2, y = (r.top + r.bottom) / 2;
      for (const f of frames) {
        const inside = x > f.left && x < f.right && y > f.top && y < f.bottom;
        if (inside && (r.left < f.left + margin || r.right > f.right - margin)) {
          lines.push('svg ' + svg.id + ' frame ' + snippet(t));
        }
      }
    }
  }
  const pre = document.createElement('pre');
  pre.id = 'measured';
  pre.textContent = lines.join('\n');
  document.body.appendChild(pre);
})();
