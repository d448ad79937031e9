"use strict";
// a BT's tick table is drawn from the page's compact traces when it is first opened
const ticks = JSON.parse(document.getElementById("ticks").textContent);
// paths are a trie: a path, or [parent number, last part]
ticks.paths.forEach((p, i) => { if (typeof p !== "string") ticks.paths[i] = ticks.paths[p[0]] + "/" + p[1]; });
function shortPath(path) {
  const parts = path.split("/");
  return (parts.length > 3 ? "…/" : "") + parts.slice(-3).join("/");
}
function traceRows(n) {
  const flat = ticks.traces[Number(n)] || [], rows = [];
  for (let i = 0; i + 1 < flat.length; i += 2) {
    const [node, status, p] = ticks.steps[flat[i + 1]];
    rows.push([String(flat[i]), node, status, ticks.paths[p]]);
  }
  return rows;
}
function drawTicks(box) {
  if (box.dataset.drawn !== undefined) return;
  box.dataset.drawn = "";
  const table = document.createElement("table"), head = table.createTHead().insertRow(), body = table.createTBody();
  table.className = "ticks";
  for (const h of ["tick", "node", "status", "where"]) head.appendChild(document.createElement("th")).textContent = h;
  for (const [tick, node, status, path] of traceRows(box.dataset.trace)) {
    const tr = body.insertRow();
    tr.className = "st-" + status.toLowerCase();
    for (const text of [tick, node, status, shortPath(path)]) tr.insertCell().textContent = text;
    tr.cells[3].title = path;  // the full tree path on hover
  }
  const after = box.querySelector("summary ~ p.msg");
  box.insertBefore(table, after ? after.nextSibling : box.querySelector("summary").nextSibling);
}
document.querySelectorAll("details.bt[data-trace]").forEach(box => {
  // drawn on the click itself (before the box opens), and on any other way of opening it
  box.querySelector("summary").addEventListener("click", () => drawTicks(box));
  box.addEventListener("toggle", () => { if (box.open) drawTicks(box); });
  if (box.open) drawTicks(box);
});
// the filter reads a card's traces too (nodes with their ports, statuses, where), drawn or not
window.filterText = el => Array.from(el.querySelectorAll("details.bt[data-trace]"), box =>
  traceRows(box.dataset.trace).map(([, node, status, path]) => `${node} ${status} ${shortPath(path)}`).join(" ")).join(" ");
"use strict";
function sortTable(th) {
  const table = th.closest("table"), body = table.tBodies[0], col = Number(th.dataset.col);
  const dir = table.dataset.col == col && table.dataset.dir == "desc" ? "asc" : "desc";
  const key = r => { const c = r.cells[col]; if (!c) return ""; const v = c.dataset.v;
    return v !== undefined && v !== "" ? Number(v) : c.textContent.trim().toLowerCase(); };
  const rows = Array.from(body.rows);
  rows.sort((a, b) => { const x = key(a), y = key(b);
    const c = typeof x === typeof y ? (x < y ? -1 : x > y ? 1 : 0) : (typeof x === "number" ? -1 : 1);
    return dir == "asc" ? c : -c; });
  rows.forEach(r => body.appendChild(r));
  table.dataset.col = col; table.dataset.dir = dir;
}
document.querySelectorAll("th[data-col]").forEach(th => th.addEventListener("click", () => sortTable(th)));
const box = document.getElementById("filter");
function applyFilter() {
  const terms = box.value.trim().toLowerCase().split(/\s+/).filter(Boolean);
  let shown = 0, total = 0;
  document.querySelectorAll("[data-filter]").forEach(el => {
    // data-text: the element's own text is searched too (a detail card: its lists, and its
    // traces through the page's filterText, drawn or not)
    if (el.searchText === undefined)
      el.searchText = (el.dataset.filter + (el.dataset.text !== undefined ? " " + el.textContent : "")
        + (el.dataset.text !== undefined && window.filterText ? " " + window.filterText(el) : "")).toLowerCase();
    const text = el.searchText;
    // rows of the index match every word; a method's table row or reasons match any word
    const hit = el.dataset.any !== undefined
      ? terms.length == 0 || terms.some(w => text.includes(w))
      : terms.every(w => text.includes(w));
    el.hidden = !hit;
    if (el.dataset.count !== undefined) { total += 1; shown += hit ? 1 : 0; }
  });
  document.querySelectorAll("[data-group]").forEach(g => {
    g.hidden = terms.length > 0 && !g.querySelector("[data-filter]:not([hidden])");
  });
  const out = document.getElementById("filter-count");
  if (out) out.textContent = terms.length ? shown + " of " + total + " shown" : "";
}
if (box) {
  box.addEventListener("input", applyFilter);
  window.addEventListener("hashchange", () => {
    const t = document.getElementById(decodeURIComponent(location.hash.slice(1)));
    if (t && t.closest("[hidden]")) { box.value = ""; applyFilter(); t.scrollIntoView(); }
  });
}
