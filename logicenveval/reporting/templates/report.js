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
