#include "live/live_page.h"

namespace prt {

// The page keeps no state on the server: it polls /status.json every 0.5 s, reloads the
// images when their version changed (at most every 1.5 s), and stops polling once the render
// has ended. A failed poll is retried and shown ("connection lost") without clearing what is
// on the page. `data-updates` on <body> counts the snapshots it drew.
const std::string& livePageHtml() {
  static const std::string html = R"PAGE(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>PRT: rendering</title>
<style>
body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222;background:#fafafa}
h1{font-size:1.3em;margin:0 0 .3em}
#bar{height:14px;background:#ddd;border-radius:7px;overflow:hidden;max-width:640px}
#fill{height:100%;width:0;background:#2a7ab0;transition:width .3s}
#summary{margin:.4em 0 1em;font-variant-numeric:tabular-nums}
.images{display:flex;gap:1em;flex-wrap:wrap}
figure{margin:0}figcaption{color:#555;font-size:.9em}
img{image-rendering:pixelated;max-width:48vw;border:1px solid #ccc;background:#333}
table{border-collapse:collapse;margin-top:1em;font-variant-numeric:tabular-nums}
th,td{padding:.2em .7em;text-align:right;border-bottom:1px solid #e4e4e4}
th{background:#eee}td.state{text-align:left}
tr.lost td{color:#b00}tr.idle td.state{color:#888}
#end{display:none;margin:1em 0;padding:.6em 1em;border-radius:6px;background:#e6f4e6}
#end.failed{background:#fbe9e9}#conn{color:#b00}
.swatch{display:inline-block;width:.8em;height:.8em;border-radius:2px;margin-right:.3em}
</style></head>
<body data-updates="0" data-phase="starting">
<h1 id="title">PRT: rendering</h1>
<div id="bar"><div id="fill"></div></div>
<div id="summary">waiting for the first snapshot&hellip; <span id="conn"></span></div>
<div id="end"></div>
<div class="images">
<figure><img id="image" alt="the image so far"><figcaption>The image so far (grey squares: not rendered yet)</figcaption></figure>
<figure id="ownfig"><img id="ownership" alt="ownership map"><figcaption>Who rendered each pixel</figcaption></figure>
</div>
<table id="workers" hidden><thead><tr><th>worker</th><th>state</th><th>pixels</th>
<th>share</th><th>pixels/s</th><th>last heard</th><th>joined / lost</th></tr></thead>
<tbody></tbody></table>
<script>
"use strict";
const token = new URLSearchParams(location.search).get("token");
const q = token ? "token=" + encodeURIComponent(token) : "";
const url = (path, extra) => path + "?" + [q, extra].filter(Boolean).join("&");
const palette = ["#1f78b5","#ff800d","#2ba12b","#d62629","#9466bd","#8c5749","#e378c2","#808080","#bdbd21","#17bfcf"];
const $ = id => document.getElementById(id);
const fmt = s => s == null ? "estimating" : s < 10 ? s.toFixed(1) + " s" : s < 60 ? Math.round(s) + " s"
  : s < 3600 ? Math.floor(s / 60) + " min " + String(Math.round(s % 60)).padStart(2, "0") + " s"
  : Math.floor(s / 3600) + " h " + String(Math.round(s / 60 % 60)).padStart(2, "0") + " min";
const num = n => Math.round(n).toLocaleString("en");
let updates = 0, imageVersion = -1, lastImageLoad = 0, ended = false;
function loadImages(version, force) {
  const now = Date.now();
  if (!force && (version === imageVersion || now - lastImageLoad < 1500)) return;
  imageVersion = version; lastImageLoad = now;
  $("image").src = url("/image.png", "v=" + version);
  $("ownership").src = url("/ownership.png", "v=" + version);
}
function cell(tr, text, cls) { const td = tr.insertCell(); td.textContent = text; if (cls) td.className = cls; return td; }
function draw(s) {
  document.body.dataset.updates = String(++updates);
  document.body.dataset.phase = s.phase;
  const name = s.output ? s.output.split("/").pop() : "image";
  $("title").textContent = "PRT: " + (s.phase === "finished" ? "rendered " : s.phase === "failed" ? "stopped: " : "rendering ") + name;
  document.title = $("title").textContent;
  const frac = s.pixels_total ? s.pixels_done / s.pixels_total : 0;
  $("fill").style.width = (100 * frac).toFixed(2) + "%";
  $("summary").firstChild.textContent = s.summary + " \u00b7 " + s.width + "\u00d7" + s.height +
    (s.frames > 1 ? ", " + s.frames + " frames" : "") + " \u00b7 " + s.driver +
    (s.strategy ? ", strategy " + s.strategy : "") + " ";
  $("ownfig").hidden = s.workers.length === 0;
  const body = $("workers").tBodies[0];
  body.replaceChildren();
  $("workers").hidden = s.workers.length === 0;
  for (const w of s.workers) {
    const tr = body.insertRow();
    tr.className = "worker " + w.state;
    const id = cell(tr, "");
    const sw = document.createElement("span"); sw.className = "swatch"; sw.style.background = palette[w.id % 10];
    id.append(sw, String(w.id));
    cell(tr, w.state, "state");
    cell(tr, num(w.pixels));
    cell(tr, (100 * w.share).toFixed(1) + "%");
    cell(tr, num(w.pixels_per_s));
    cell(tr, w.state === "lost" ? "\u2014" : fmt(w.silent_s) + " ago");
    cell(tr, w.lost_at_s != null ? "lost at " + fmt(w.lost_at_s) + " (" + w.lost_reason + ")"
           : w.joined_at_s != null ? "joined at " + fmt(w.joined_at_s) : "\u2014");
  }
  if (s.phase === "finished" || s.phase === "failed") {
    ended = true;
    const end = $("end");
    end.style.display = "block";
    end.className = s.phase;
    end.replaceChildren();
    if (s.phase === "finished") {
      end.append("Finished in " + fmt(s.elapsed_s) + ". The image is written to " + s.output + " \u2014 ");
      const a = document.createElement("a"); a.href = url("/image.png", "final=1"); a.textContent = "the final image";
      end.append(a, ".");
    } else {
      end.append("The render stopped: " + s.message);
    }
    loadImages(s.version, true);
  } else if (s.pixels_done > 0) {
    loadImages(s.version, false);
  }
}
async function poll() {
  try {
    const r = await fetch(url("/status.json"), {cache: "no-store"});
    if (!r.ok) throw new Error("HTTP " + r.status);
    draw(await r.json());
    $("conn").textContent = "";
  } catch (e) {
    $("conn").textContent = ended ? "" : "(connection lost: retrying)";
  }
  if (!ended) setTimeout(poll, 500);
}
poll();
</script></body></html>
)PAGE";
  return html;
}

}  // namespace prt
