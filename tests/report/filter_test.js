// The report's filter (renderer/report/assets/report.js, setUpFilter) on stand-in rows, without a browser:
// every word of the text must match (any case, any order, any column's words), and the count names what
// the rows are. The same filter in a real browser: browser_test.py.
// Usage: node filter_test.js REPORT_JS
"use strict";
const fs = require("fs");
const vm = require("vm");
const assert = require("assert");

const context = { document: { addEventListener() {} }, console };
vm.createContext(context);
vm.runInContext(fs.readFileSync(process.argv[2], "utf8"), context);

function table(names, noun) {
  const rows = names.map((name) => ({ dataset: { name, verdict: "" }, hidden: false }));
  return { rows, dataset: noun ? { noun } : {}, querySelectorAll: () => rows };
}
function filter(t, text) {
  let listener = null;
  const input = { value: text, addEventListener: (_, f) => { listener = f; } };
  const status = { textContent: "" };
  context.setUpFilter(input, t, status);
  return { shown: t.rows.filter((r) => !r.hidden).map((r) => r.dataset.name), status: status.textContent };
}

const rows = ["chrome MERL studio preview Smooth E2 smooth:E2 published",
              "chrome MERL sky preview Smooth E2 smooth:E2 published",
              "gold-paint RGL-EPFL studio preview CT E2 cook-torrance:E2 glossy"];
let r = filter(table(rows, "rows"), "studio smooth");
assert.deepStrictEqual(r.shown, [rows[0]], "words are ANDed: " + JSON.stringify(r));
assert.strictEqual(r.status, "1 of 3 rows shown");
r = filter(table(rows, "rows"), "  SMOOTH   Studio ");
assert.deepStrictEqual(r.shown, [rows[0]], "any case, any order, any spacing");
r = filter(table(rows, "rows"), "rgl-epfl");
assert.deepStrictEqual(r.shown, [rows[2]], "the database matches");
r = filter(table(rows, "rows"), "cook-torrance:E2");
assert.deepStrictEqual(r.shown, [rows[2]], "the fit matches");
r = filter(table(rows, "rows"), "");
assert.strictEqual(r.shown.length, 3);
r = filter(table(["alum-bronze", "chrome"]), "chrome");
assert.strictEqual(r.status, "1 of 2 materials shown", "the index counts materials");
console.log("filter_test: ok");
