#!/bin/sh
# package-blender-addon.sh [ZIP]: the Blender add-on (integrations/blender/prt_render/) as the
# zip Blender installs (Edit > Preferences > Add-ons > Install..., or
# bpy.ops.preferences.addon_install): one folder prt_render/ at the zip's top. Default ZIP:
# build/prt_render.zip. Written whole or not at all (a temporary file, then renamed).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
zip=${1:-$root/build/prt_render.zip}
case $zip in /*) ;; *) zip=$PWD/$zip ;; esac
mkdir -p "$(dirname "$zip")"
tmp="$zip.tmp-$$"
trap 'rm -f "$tmp"' EXIT
# Python's zipfile (Blender needs Python anyway): no zip package needed, the same bytes each
# time for the same sources (fixed dates, sorted names).
python3 - "$root/integrations/blender" "$tmp" <<'PY'
import os, sys, zipfile
source, out = sys.argv[1], sys.argv[2]
names = []
for folder, dirs, files in os.walk(os.path.join(source, "prt_render")):
    dirs[:] = sorted(d for d in dirs if d != "__pycache__")
    names += [os.path.join(folder, f) for f in files if f.endswith(".py")]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for path in sorted(names):
        info = zipfile.ZipInfo(os.path.relpath(path, source), (2024, 1, 1, 0, 0, 0))
        info.external_attr = 0o644 << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        with open(path, "rb") as f:
            z.writestr(info, f.read())
PY
mv "$tmp" "$zip"
trap - EXIT
echo "package-blender-addon: wrote $zip"
