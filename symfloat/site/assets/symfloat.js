/* Open the note a link points to (a <details> element), on arrival and on every in-page jump. */
function symfloatOpenTarget() {
  var id = decodeURIComponent(location.hash.slice(1));
  var target = id && document.getElementById(id);
  if (target && target.tagName === "DETAILS") { target.open = true; }
}
window.addEventListener("hashchange", symfloatOpenTarget);
window.addEventListener("DOMContentLoaded", symfloatOpenTarget);
