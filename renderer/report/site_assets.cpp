// The report's style sheet and script (site_assets.h), kept here as raw strings so the executable carries
// its site with it.
#include "renderer/report/site_assets.h"

namespace glossy::report {

std::string_view siteStyleSheet() {
  return R"css(/* glossy report: one style sheet for the index and the material pages. */
:root {
  --fg: #1d2127; --muted: #5b6470; --bg: #fbfbfa; --panel: #ffffff; --line: #d9dde2; --accent: #0b62a4;
  --image-bg: #1f1f1f; --good: #e8f3ea;
  color-scheme: light;
}
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.45 system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif; color: var(--fg); background: var(--bg); }
header.site, main, footer.site { max-width: 1400px; margin: 0 auto; padding: 0 1.25rem; }
header.site { padding-top: 1.25rem; }
header.site h1 { margin: 0.2rem 0 0.3rem; font-size: 1.6rem; }
header.site p { margin: 0.2rem 0; color: var(--muted); max-width: 70rem; }
footer.site { color: var(--muted); font-size: 0.85rem; padding-bottom: 2rem; }
h2 { font-size: 1.2rem; margin: 1.8rem 0 0.6rem; border-bottom: 1px solid var(--line); padding-bottom: 0.2rem; }
a { color: var(--accent); }
nav.crumbs { font-size: 0.9rem; display: flex; gap: 1rem; flex-wrap: wrap; }
.muted { color: var(--muted); }
code, .params { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 0.85em; }
.controls { display: flex; gap: 0.75rem; align-items: center; flex-wrap: wrap; margin: 1rem 0 0.5rem; }
.controls input { font: inherit; padding: 0.35rem 0.6rem; min-width: 18rem; border: 1px solid var(--line); border-radius: 6px; }
.table-wrap { overflow-x: auto; border: 1px solid var(--line); border-radius: 8px; background: var(--panel); }
table { border-collapse: collapse; font-variant-numeric: tabular-nums; }
th, td { padding: 0.3rem 0.5rem; border-bottom: 1px solid var(--line); text-align: right; white-space: nowrap; }
th { font-weight: 600; background: #f1f3f5; vertical-align: bottom; }
td.text, th.text { text-align: left; }
tbody th { vertical-align: middle; }
tbody tr:hover td { background: #f6f8fa; }
th.group { text-align: center; border-left: 2px solid var(--line); border-top: 4px solid var(--model-colour, var(--line)); }
.group-start { border-left: 2px solid var(--line); }
#materials td.name, #materials th.name { position: sticky; left: 0; background: var(--panel); z-index: 1; text-align: left; }
#materials th.name { background: #f1f3f5; z-index: 2; }
th button.sort { font: inherit; font-weight: 600; background: none; border: 0; padding: 0.1rem 0.2rem; cursor: pointer; color: inherit; }
th button.sort::after { content: " \2195"; color: #9aa3ad; }
th[aria-sort="ascending"] button.sort::after { content: " \25B2"; color: var(--accent); }
th[aria-sort="descending"] button.sort::after { content: " \25BC"; color: var(--accent); }
th button.sort:focus-visible, button:focus-visible, input:focus-visible { outline: 2px solid var(--accent); outline-offset: 1px; }
td.thumb { padding: 2px 6px; }
td.thumb img { display: block; width: 48px; height: 48px; image-rendering: auto; background: var(--image-bg); border-radius: 3px; }
td.best { background: var(--good); font-weight: 600; }
td.closest-mark { color: #226633; font-weight: 600; }
.verdict { font-weight: 600; }
#materials td.verdict { white-space: normal; min-width: 9rem; max-width: 15rem; font-weight: 500; }
td.note { white-space: normal; min-width: 14rem; max-width: 32rem; text-align: left; overflow-wrap: anywhere; }
.summary td.model { text-align: left; border-left: 6px solid var(--model-colour, var(--line)); }
figure { margin: 0; }
figure img { max-width: 100%; height: auto; background: var(--image-bg); }
figcaption { color: var(--muted); font-size: 0.9rem; margin-top: 0.3rem; max-width: 70rem; }
.sheet img { image-rendering: auto; }
.sheet-panels { position: relative; background: #000; }
.sheet-panels img { position: absolute; display: block; max-width: none; }
.sheet-lower { display: block; width: 100%; height: auto; }
dl.meta { display: grid; grid-template-columns: max-content 1fr; gap: 0.15rem 1rem; margin: 0.5rem 0; }
dl.meta dt { color: var(--muted); }
dl.meta dd { margin: 0; overflow-wrap: anywhere; }
.compare { display: flex; gap: 1.5rem; flex-wrap: wrap; align-items: flex-start; width: fit-content; max-width: 100%; }
.compare-view { background: var(--image-bg); padding: 8px; border-radius: 8px; }
.compare-view img { display: block; width: 384px; max-width: 80vw; height: auto; image-rendering: pixelated; cursor: crosshair; }
.compare-label { color: #f3f3f3; margin: 0.4rem 0 0; font-weight: 600; text-align: center; }
.compare-controls { display: flex; flex-direction: column; gap: 0.4rem; flex: 1 1 18rem; max-width: 36rem; }
.compare-controls .models { display: flex; flex-wrap: wrap; gap: 0.35rem; }
.compare-controls button { font: inherit; padding: 0.35rem 0.7rem; border-radius: 6px; border: 1px solid var(--line); background: var(--panel); cursor: pointer;
  border-left: 5px solid var(--model-colour, var(--line)); }
.compare-controls button[aria-pressed="true"] { background: #dbe9f6; border-color: var(--accent); }
.compare-controls button:disabled { opacity: 0.5; cursor: not-allowed; }
.compare-controls button.toggle { border-left-width: 1px; font-weight: 600; align-self: flex-start; }
.plots { display: grid; grid-template-columns: repeat(auto-fill, minmax(340px, 1fr)); gap: 1.2rem; }
.plots figure { background: var(--panel); border: 1px solid var(--line); border-radius: 8px; padding: 0.6rem; }
.plots figure img { background: #fff; }
.plots h3 { font-size: 1rem; margin: 0 0 0.4rem; }
noscript p { background: #fff4d6; padding: 0.4rem 0.7rem; border-radius: 6px; }
)css";
}

std::string_view siteScript() {
  return R"js(// glossy report: sorting and filtering the index, and the compare view of a material page.
"use strict";

// Sorting: a header's button sorts the rows by that column; numbers by their data-value, text by its
// content; missing values last in either direction; equal values keep their order (stable).
function setUpSorting(table) {
  const body = table.querySelector("tbody.rows");
  if (!body) return;
  Array.from(body.rows).forEach((row, i) => { row.dataset.index = String(i); });
  const headers = Array.from(table.querySelectorAll("th[data-col]"));
  for (const th of headers) {
    const button = th.querySelector("button.sort");
    if (!button) continue;
    button.addEventListener("click", () => {
      const ascending = th.getAttribute("aria-sort") !== "ascending";
      for (const other of headers) other.removeAttribute("aria-sort");
      th.setAttribute("aria-sort", ascending ? "ascending" : "descending");
      sortRows(body, Number(th.dataset.col), th.dataset.type === "text", ascending);
    });
  }
}

function cellKey(row, col, isText) {
  const cell = row.cells[col];
  if (!cell) return null;
  if (isText) {
    const text = (cell.dataset.value !== undefined ? cell.dataset.value : cell.textContent).trim().toLowerCase();
    return text === "" ? null : text;
  }
  const raw = cell.dataset.value;
  if (raw === undefined || raw === "") return null;
  const v = Number(raw);
  return Number.isFinite(v) ? v : null;
}

function sortRows(body, col, isText, ascending) {
  const rows = Array.from(body.rows).map((row) => ({ row, key: cellKey(row, col, isText), index: Number(row.dataset.index) }));
  rows.sort((a, b) => {
    if (a.key === null || b.key === null) {
      if (a.key === null && b.key === null) return a.index - b.index;
      return a.key === null ? 1 : -1;
    }
    // Text by code units, not the locale's collation: the same order on every machine.
    let c = isText ? (a.key < b.key ? -1 : a.key > b.key ? 1 : 0) : a.key - b.key;
    if (!ascending) c = -c;
    return c !== 0 ? c : a.index - b.index;
  });
  for (const r of rows) body.appendChild(r.row);
}

// Filtering: rows whose material name or verdict contains the text (any case) stay shown.
function setUpFilter(input, table, status) {
  const rows = Array.from(table.querySelectorAll("tbody.rows tr"));
  const apply = () => {
    const q = input.value.trim().toLowerCase();
    let shown = 0;
    for (const row of rows) {
      const text = ((row.dataset.name || "") + " " + (row.dataset.verdict || "")).toLowerCase();
      row.hidden = q !== "" && !text.includes(q);
      if (!row.hidden) ++shown;
    }
    if (status) status.textContent = shown + " of " + rows.length + " materials shown";
  };
  input.addEventListener("input", apply);
  apply();
}

// The compare view: the model buttons choose the panel; the toggle (or the pointer over the image) shows
// the measured panel in its place, at the same exposure, and the label says which one is shown.
function setUpCompare(root) {
  const img = root.querySelector("img.compare-image");
  const label = root.querySelector(".compare-label");
  const toggle = root.querySelector("button.toggle");
  const models = Array.from(root.querySelectorAll("button.model"));
  const measured = { src: img.dataset.measuredSrc || "", label: img.dataset.measuredLabel || "Measured" };
  let current = models.find((b) => b.getAttribute("aria-pressed") === "true") || null;
  let pinned = false, hovering = false;
  const show = () => {
    const wantMeasured = (pinned || hovering) && measured.src !== "";
    const src = wantMeasured ? measured.src : current ? current.dataset.src : measured.src;
    const text = wantMeasured || !current ? measured.label : current.dataset.label;
    if (src && img.getAttribute("src") !== src) img.setAttribute("src", src);
    img.alt = text + " panel";
    label.textContent = "Showing: " + text;
    root.dataset.showing = wantMeasured || !current ? "measured" : current.dataset.layer;
    if (toggle) {
      toggle.setAttribute("aria-pressed", pinned ? "true" : "false");
      toggle.textContent = pinned ? "Show the model" : "Show measured";
    }
  };
  for (const b of models)
    b.addEventListener("click", () => {
      current = b;
      pinned = false;
      for (const o of models) o.setAttribute("aria-pressed", o === b ? "true" : "false");
      show();
    });
  if (toggle && measured.src !== "") {
    toggle.addEventListener("click", () => { pinned = !pinned; show(); });
    img.addEventListener("mouseenter", () => { hovering = true; show(); });
    img.addEventListener("mouseleave", () => { hovering = false; show(); });
  }
  show();
}

document.addEventListener("DOMContentLoaded", () => {
  const table = document.getElementById("materials");
  if (table) {
    setUpSorting(table);
    const filter = document.getElementById("filter");
    if (filter) setUpFilter(filter, table, document.getElementById("shown"));
  }
  for (const root of document.querySelectorAll(".compare")) setUpCompare(root);
});
)js";
}

}  // namespace glossy::report
