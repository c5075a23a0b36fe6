// The run page's interaction: draws the ownership map from the embedded report and
// highlights a worker (or a group of workers) everywhere when it is hovered or clicked.
(function () {
  'use strict';
  var run = JSON.parse(document.getElementById('prt-run').textContent);
  var page = JSON.parse(document.getElementById('prt-page').textContent);
  var map = run.ownership_map;
  var owners = map && map.data ? decode(map) : null;  // left out of a huge report: none
  var colours = page.colours.map(function (hex) {
    return [parseInt(hex.slice(1, 3), 16), parseInt(hex.slice(3, 5), 16),
            parseInt(hex.slice(5, 7), 16)];
  });
  var shade = null;   // per map sample, 0..1: the picture's brightness
  var pinned = null;  // [first, last] kept by a click
  var canvas = document.getElementById('ownership');
  var overlay = document.getElementById('picture-overlay');
  var picture = document.getElementById('picture');
  var picked = document.getElementById('picked');
  var defaultPicked = picked ? picked.textContent : '';

  // Runs of (owner + 1, length) as unsigned LEB128 varints, base64 (report/ownership_map.h).
  function decode(m) {
    var bytes = atob(m.data), out = new Int32Array(m.width * m.height), i = 0, n = 0;
    function varint() {
      var v = 0, scale = 1, b;
      do { b = bytes.charCodeAt(i++); v += (b & 127) * scale; scale *= 128; } while (b & 128);
      return v;
    }
    while (i < bytes.length && n < out.length) {
      var owner = varint() - 1, length = varint();
      for (var k = 0; k < length && n < out.length; k++) out[n++] = owner;
    }
    return out;
  }

  function brightness() {
    if (!picture || !page.picture_is_render || !map) return null;
    try {
      var c = document.createElement('canvas');
      c.width = map.width; c.height = map.height;
      var g = c.getContext('2d');
      g.drawImage(picture, 0, 0, map.width, map.height);
      var d = g.getImageData(0, 0, map.width, map.height).data, out = new Float32Array(map.width * map.height);
      for (var p = 0; p < out.length; p++) {
        out[p] = Math.sqrt((0.2126 * d[4 * p] + 0.7152 * d[4 * p + 1] + 0.0722 * d[4 * p + 2]) / 255);
      }
      return out;
    } catch (e) {
      return null;  // a browser that will not read the image back: flat colours
    }
  }

  function draw(sel) {
    if (!canvas || !owners) return;
    canvas.width = map.width; canvas.height = map.height;
    var g = canvas.getContext('2d'), img = g.createImageData(map.width, map.height), d = img.data;
    for (var p = 0; p < owners.length; p++) {
      var o = owners[p], c = o >= 0 && o < colours.length ? colours[o] : [30, 30, 30];
      var f = shade ? 0.45 + 0.55 * shade[p] : 1;
      var off = sel && (o < sel[0] || o > sel[1]);
      for (var k = 0; k < 3; k++) d[4 * p + k] = off ? 0.25 * c[k] * f + 180 : c[k] * f;
      d[4 * p + 3] = 255;
    }
    g.putImageData(img, 0, 0);
    if (overlay) {
      overlay.width = map.width; overlay.height = map.height;
      var h = overlay.getContext('2d');
      if (sel) {
        var o2 = h.createImageData(map.width, map.height), e = o2.data;
        for (var q = 0; q < owners.length; q++) {
          if (owners[q] < sel[0] || owners[q] > sel[1]) e[4 * q + 3] = 190;
        }
        h.putImageData(o2, 0, 0);
      }
    }
  }

  var current = null;  // what is highlighted now: mousemove over one worker redraws once
  function highlight(sel) {
    if (same(sel, current) || (!sel && !current)) return;
    current = sel;
    draw(sel);
    var nodes = document.querySelectorAll('[data-first]');
    for (var i = 0; i < nodes.length; i++) {
      var a = +nodes[i].getAttribute('data-first'), b = +nodes[i].getAttribute('data-last');
      var on = sel && a <= sel[1] && b >= sel[0];
      nodes[i].classList.toggle('sel', !!on);
      if (nodes[i].classList.contains('row')) nodes[i].classList.toggle('dim', !!sel && !on);
    }
    if (picked) {
      if (!sel) picked.textContent = defaultPicked;
      else if (sel[0] === sel[1]) picked.textContent = page.info[sel[0]] || ('worker ' + sel[0]);
      else picked.textContent = 'workers ' + sel[0] + '–' + sel[1];
      if (sel && pinned) picked.textContent += ' (kept: click again to let go)';
    }
  }

  function rangeOf(node) {
    return [+node.getAttribute('data-first'), +node.getAttribute('data-last')];
  }
  function same(a, b) { return a && b && a[0] === b[0] && a[1] === b[1]; }
  function hover(sel) { if (!pinned) highlight(sel); }
  function click(sel) {
    pinned = same(pinned, sel) ? null : sel;
    current = null;  // the note under the map changes (kept or not): refresh it
    highlight(pinned || sel);
  }

  var targets = document.querySelectorAll('[data-first]');
  for (var i = 0; i < targets.length; i++) {
    targets[i].addEventListener('mouseenter', function () { hover(rangeOf(this)); });
    targets[i].addEventListener('mouseleave', function () { hover(null); });
    targets[i].addEventListener('click', function () { click(rangeOf(this)); });
  }
  function ownerAt(ev) {
    var r = canvas.getBoundingClientRect();
    var x = Math.floor((ev.clientX - r.left) / r.width * map.width);
    var y = Math.floor((ev.clientY - r.top) / r.height * map.height);
    if (x < 0 || y < 0 || x >= map.width || y >= map.height) return -1;
    return owners[y * map.width + x];
  }
  if (canvas && owners) {
    canvas.addEventListener('mousemove', function (ev) {
      var o = ownerAt(ev);
      hover(o >= 0 ? [o, o] : null);
    });
    canvas.addEventListener('mouseleave', function () { hover(null); });
    canvas.addEventListener('click', function (ev) {
      var o = ownerAt(ev);
      if (o >= 0) click([o, o]);
    });
  }
  document.addEventListener('keydown', function (ev) {
    if (ev.key === 'Escape') { pinned = null; highlight(null); }
  });

  // #worker=N in the address keeps worker N picked, for links and screenshots.
  function start() {
    shade = brightness();
    var m = /worker=(\d+)/.exec(location.hash);
    var w = m ? +m[1] : -1;
    if (w >= 0 && w < colours.length) click([w, w]); else draw(null);
    document.documentElement.setAttribute('data-page-ready', 'yes');
  }
  if (picture && !picture.complete) picture.addEventListener('load', start); else start();
})();
