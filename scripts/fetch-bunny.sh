#!/usr/bin/env bash
# Fetches the Stanford bunny (the npm package `bunny`, 1.0.1: public domain, from the Stanford
# 3D Scanning Repository; 1,839 vertices, 3,674 triangles) and writes it as a binary
# little-endian PLY file, scenes/models/bunny.ply, for the example scene bunny.scene. The
# triangles are wound counter-clockwise seen from outside (turned over if the package's are
# not: the enclosed volume must come out positive). Safe to run again: an existing file is kept.
set -euo pipefail
cd "$(dirname "$0")/.."
out=scenes/models/bunny.ply
if [[ -s $out ]]; then
  echo "fetch-bunny: $out present"
  exit 0
fi
for tool in npm node; do
  if ! command -v "$tool" >/dev/null; then
    echo "fetch-bunny: needs $tool (Debian package npm)" >&2
    exit 1
  fi
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm pack --silent bunny@1.0.1 >/dev/null && tar xzf bunny-1.0.1.tgz)
mkdir -p "$(dirname "$out")"
node - "$tmp/package/index.js" "$out.tmp" <<'JS'
const fs = require("fs");
const [source, target] = process.argv.slice(2);
const { positions, cells } = require(source);
// Six times the enclosed volume: positive when the faces are wound outwards.
let volume = 0;
for (const [a, b, c] of cells) {
  const [p, q, r] = [positions[a], positions[b], positions[c]];
  volume += p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
            p[2] * (q[0] * r[1] - q[1] * r[0]);
}
const flip = volume < 0;
const header = "ply\nformat binary_little_endian 1.0\n" +
    "comment Stanford bunny, npm package bunny 1.0.1 (public domain)\n" +
    `element vertex ${positions.length}\nproperty float x\nproperty float y\nproperty float z\n` +
    `element face ${cells.length}\nproperty list uchar int vertex_indices\nend_header\n`;
const body = Buffer.alloc(positions.length * 12 + cells.length * 13);
let at = 0;
for (const p of positions) for (const x of p) { body.writeFloatLE(x, at); at += 4; }
for (const c of cells) {
  body.writeUInt8(3, at++);
  for (const i of flip ? [c[0], c[2], c[1]] : c) { body.writeInt32LE(i, at); at += 4; }
}
fs.writeFileSync(target, Buffer.concat([Buffer.from(header, "ascii"), body]));
console.log(`fetch-bunny: ${positions.length} vertices, ${cells.length} triangles` +
            (flip ? " (turned outwards)" : ""));
JS
mv "$out.tmp" "$out"
echo "fetch-bunny: wrote $out"
