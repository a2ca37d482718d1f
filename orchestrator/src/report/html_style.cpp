// SPDX-License-Identifier: GPL-3.0-or-later
// The report pages' style sheet (see html_style.h).
#include "report/html_style.h"

namespace gridfree {

namespace {

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 2em auto; max-width: 1400px; padding: 0 1em; color: #222; box-sizing: border-box; }
h1 { font-size: 1.6em; } h2 { margin-top: 2em; border-bottom: 1px solid #ccc; } h3 { font-size: 1.05em; }
dl.summary { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1em; }
dl.summary dt { font-weight: bold; } dl.summary dd { margin: 0; }
nav.toc { columns: 2; font-size: 0.9em; } nav.toc ul { margin: 0.2em 0; } nav.toc > div { break-inside: avoid; }
nav.toc a { overflow-wrap: anywhere; }
@media (max-width: 700px) { nav.toc { columns: 1; } }
.filter { margin: 0.5em 0; } .filter input { font-size: 1em; width: 22em; max-width: 100%; }
.attention { background: #fff4e5; border-left: 4px solid #e69f00; padding: 0.5em 1em; }
.scroll { overflow-x: auto; }
table.data { border-collapse: collapse; font-size: 0.85em; margin: 0.5em 0; }
table.data th, table.data td { border: 1px solid #ccc; padding: 0.2em 0.5em; white-space: nowrap; }
table.data td.prose { white-space: normal; min-width: 18em; max-width: 36em; }
table.data th { background: #f2f2f2; } table.data td.num { text-align: right; font-variant-numeric: tabular-nums; }
table.data tr:nth-child(even) td { background: #fafafa; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(620px, 100%), 1fr)); gap: 0 1.5em; }
figure { margin: 1em 0; } figure svg { max-width: 100%; height: auto; }
.chart-narrow { display: none; }
section.answer .counts { font-size: 1.15em; margin: 0.4em 0; }
table.answer-table { font-size: 0.95em; }
.attention ul { margin: 0.3em 0; padding-left: 1.2em; } .attention li { margin: 0.15em 0; }
@media (max-width: 700px) {
  body { margin: 0.5em auto; padding: 0 0.5em; }
  .chart-wide { display: none; } .chart-narrow { display: block; }
  .chart-narrow svg { width: 100%; max-width: 420px; }
  figure.stability-figure svg { max-width: none; }  /* 1:1 (11 px text), scrolling sideways in its box */
  table.data { font-size: 0.8em; }
  table.data td:first-child { white-space: normal; min-width: 7em; }  /* the name wraps, f0 ± U stays in view */
  h1 { font-size: 1.3em; }
  dl.summary { display: block; font-size: 0.9em; } dl.summary dd { margin: 0 0 0.3em 1em; }
}
figcaption { font-size: 0.9em; color: #444; max-width: 720px; }
p.note { font-size: 0.9em; color: #444; max-width: 900px; }
div.verdict { border-left: 4px solid #999; padding: 0 1em; margin: 0.5em 0; }
div.verdict-converged { border-color: #009e73; } div.verdict-pre-asymptotic { border-color: #e69f00; }
div.verdict-unreliable, div.verdict-insufficient_grids { border-color: #d55e00; }
div.verdict .word { font-weight: bold; } div.verdict ul { margin: 0.2em 0 0.5em; }
@page { size: A4; margin: 10mm; }
@page landscape { size: A4 landscape; margin: 10mm; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 9pt; }
  .scroll { overflow: visible; }
  table.data { font-size: 6.5pt; table-layout: auto; }
  table.data.fit-landscape-small { font-size: 5pt; }
  section:has(> .scroll > table.fit-landscape, > .scroll > table.fit-landscape-small),
  .print-block:has(> .scroll > table.fit-landscape, > .scroll > table.fit-landscape-small),
  .scroll:has(> table.fit-landscape, > table.fit-landscape-small) { page: landscape; }
  table.data th, table.data td { white-space: normal; overflow-wrap: normal; word-break: normal; padding: 1px 2px; }
  table.data td.num { white-space: nowrap; } table.data.fit-landscape-small td.num { white-space: normal; }
  table.data td.prose { min-width: 10em; }
  .charts { display: block; }
  .chart-narrow { display: none; } .chart-wide { display: block; }
  figure { break-inside: avoid; } h2, h3 { break-after: avoid; }
  /* No orphan rows: a table's last three rows and the note under it stay together. */
  table.data tr { break-inside: avoid; }
  table.data tbody tr:nth-last-child(-n+2) { break-before: avoid; }
  .scroll + p.note { break-before: avoid; }
  nav.toc { columns: 1; }
  .filter { display: none; }
  .screen-only { display: none; }
}
)css";

}  // namespace

const char* report_css() { return kStyle; }

}  // namespace gridfree
