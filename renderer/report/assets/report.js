// glossy report: sorting and filtering the index, and the compare view of a material page.
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

// Filtering: rows whose words (data-name: the material, and on the study page its database, lighting,
// scene, model and fit) and verdict contain every word of the text (any case) stay shown: "studio smooth"
// keeps the Smooth rows under the studio lighting. The count names what the table's rows are (data-noun:
// "materials" on the index, "rows" on the study page).
function setUpFilter(input, table, status) {
  const rows = Array.from(table.querySelectorAll("tbody.rows tr"));
  const noun = table.dataset.noun || "materials";
  const apply = () => {
    const words = input.value.trim().toLowerCase().split(/\s+/).filter((w) => w !== "");
    let shown = 0;
    for (const row of rows) {
      const text = ((row.dataset.name || "") + " " + (row.dataset.verdict || "")).toLowerCase();
      row.hidden = !words.every((w) => text.includes(w));
      if (!row.hidden) ++shown;
    }
    if (status) status.textContent = shown + " of " + rows.length + " " + noun + " shown";
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
