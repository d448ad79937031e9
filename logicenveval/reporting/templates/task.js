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
