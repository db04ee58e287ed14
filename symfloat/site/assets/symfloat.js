/* Open the note a link points to (a <details> element), on arrival and on every in-page jump. */
function symfloatOpenTarget() {
  var id = decodeURIComponent(location.hash.slice(1));
  var target = id && document.getElementById(id);
  if (target && target.tagName === "DETAILS") { target.open = true; }
}
window.addEventListener("hashchange", symfloatOpenTarget);
window.addEventListener("DOMContentLoaded", symfloatOpenTarget);

/* A displayed formula wider than its column is set smaller, down to SYMFLOAT_SMALLEST of its size, so that on
   a phone most displays are seen whole; one still wider scrolls in its own box and is marked "scrolls" (a shade
   at its right edge says there is more) until it is scrolled to its end.  Displays in a closed note are fitted
   when it opens.  All widths are read before any size is written: two layouts for the whole page. */
var SYMFLOAT_SMALLEST = 0.75;
function symfloatFit(root) {
  var boxes = Array.prototype.filter.call((root || document).querySelectorAll(".katex-display"),
                                          function (box) { return !box.closest("details:not([open])"); });
  boxes.forEach(function (box) { box.style.fontSize = ""; });
  var sizes = boxes.map(function (box) {
    var ratio = box.clientWidth / box.scrollWidth;
    return ratio < 1 ? parseFloat(getComputedStyle(box).fontSize) * Math.max(SYMFLOAT_SMALLEST, ratio * 0.98) : 0;
  });
  boxes.forEach(function (box, k) { if (sizes[k]) { box.style.fontSize = sizes[k] + "px"; } });
  var more = boxes.map(symfloatHasMore);
  boxes.forEach(function (box, k) { box.classList.toggle("scrolls", more[k]); });
}
function symfloatHasMore(box) { return box.scrollLeft + box.clientWidth < box.scrollWidth - 1; }
/* A table wider than its column scrolls in its own box too (the stylesheet sets it as a block): it is marked
   "scrolls" the same way, so that a column cut off at the right is not taken for the table's end. */
var SYMFLOAT_TABLES = ".body table, table.witnesses";
function symfloatTables(root) {
  var tables = Array.prototype.filter.call((root || document).querySelectorAll(SYMFLOAT_TABLES),
                                           function (t) { return !t.closest("details:not([open])"); });
  var more = tables.map(symfloatHasMore);
  tables.forEach(function (t, k) { t.classList.toggle("scrolls", more[k]); });
}
function symfloatLaidOut(root) { symfloatFit(root); symfloatTables(root); }
window.addEventListener("DOMContentLoaded", function () { symfloatLaidOut(); });
document.addEventListener("toggle", function (e) { if (e.target.open) { symfloatLaidOut(e.target); } }, true);
document.addEventListener("scroll", function (e) {
  var box = e.target;
  if (box.classList && (box.classList.contains("katex-display") || box.matches(SYMFLOAT_TABLES))) {
    box.classList.toggle("scrolls", symfloatHasMore(box));
  }
}, true);
var symfloatResized = null;
window.addEventListener("resize", function () {
  clearTimeout(symfloatResized);
  symfloatResized = setTimeout(function () { symfloatLaidOut(); }, 100);
});

/* A mark's shade and underline belong to its lines of text, whose height is the font's: a formula reaching a
   quarter of an em or more below the text (a case table, a fraction of fractions) would stand out of the shade,
   the underline drawn through its lower half.  Each such formula (KaTeX sets each run of a formula in a box of
   its own height) is marked "tall": the stylesheet shades it whole, which hides the line's underline behind it,
   and underlines it at its own foot.  All boxes are read before any class is written. */
function symfloatTallFormulas() {
  var marks = Array.prototype.filter.call(document.querySelectorAll("a.q"), function (mark) {
    return mark.querySelector(".katex-html") && !mark.closest("details:not([open])");
  });
  var bases = [];
  marks.forEach(function (mark) {
    var lines = Array.prototype.slice.call(mark.getClientRects());
    mark.querySelectorAll(".katex-html > .base").forEach(function (base) {
      var box = base.getBoundingClientRect(), middle = (box.top + box.bottom) / 2;
      var line = lines.reduce(function (best, r) {
        return Math.abs((r.top + r.bottom) / 2 - middle) < Math.abs((best.top + best.bottom) / 2 - middle) ? r : best;
      }, lines[0]);
      var quarter = 0.25 * parseFloat(getComputedStyle(mark).fontSize);
      bases.push([base, Boolean(line) && box.bottom > line.bottom + quarter]);
    });
  });
  bases.forEach(function (pair) { pair[0].classList.toggle("tall", pair[1]); });
}
window.addEventListener("DOMContentLoaded", symfloatTallFormulas);
if (document.fonts) { document.fonts.ready.then(symfloatTallFormulas); }     /* the formulas set in their own fonts */
