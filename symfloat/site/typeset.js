// symfloat site: TeX typeset by KaTeX at build time. One JSON request per line on stdin
// ({"tex": "...", "display": true}), one JSON answer per line on stdout ({"html": "..."} or {"error": "..."}).
"use strict";
const katex = require("katex");
const readline = require("readline");

console.warn = () => {};      // KaTeX warns of glyphs it has no metrics for (German quotes in \text): shown all the same

const MACROS = {"\\tg": "\\operatorname{tg}", "\\cotg": "\\operatorname{cotg}", "\\ctg": "\\operatorname{ctg}"};

readline.createInterface({input: process.stdin, terminal: false}).on("line", (line) => {
  const request = JSON.parse(line);
  let answer;
  try {
    answer = {html: katex.renderToString(request.tex, {
      displayMode: request.display, throwOnError: true, strict: "ignore",
      trust: (context) => context.command === "\\htmlClass" && context.class === "changed",  // a correction's change
      output: "htmlAndMathml", macros: Object.assign({}, MACROS)})};
  } catch (error) {
    answer = {error: String(error.message || error)};
  }
  process.stdout.write(JSON.stringify(answer) + "\n");
});
