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
window.addEventListener("DOMContentLoaded", function () { symfloatFit(); });
document.addEventListener("toggle", function (e) { if (e.target.open) { symfloatFit(e.target); } }, true);
document.addEventListener("scroll", function (e) {
  if (e.target.classList && e.target.classList.contains("katex-display")) { e.target.classList.toggle("scrolls", symfloatHasMore(e.target)); }
}, true);
var symfloatResized = null;
window.addEventListener("resize", function () {
  clearTimeout(symfloatResized);
  symfloatResized = setTimeout(function () { symfloatFit(); }, 100);
});
