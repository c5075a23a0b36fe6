#!/usr/bin/env bash
# sweep-models.sh PRT [DIR]: renders every model file under DIR (default: Debian's
# assimp-testmodels, /usr/share/assimp/models) twice, as `prt render FILE` and as the `mesh`
# of a scene, each tiny and under a time limit, and sorts the outcomes: rendered (exit 0),
# refused with a message (exit 2), and anything else: a crash, a hang (killed after 120 s) or
# another exit code, each listed (with SWEEP_VERBOSE=1 the refusals too, with their message).
# Exits 1 if there is any of those, else 0.
set -uo pipefail
prt=${1:?usage: sweep-models.sh PRT [DIR]}
dir=${2:-/usr/share/assimp/models}
[[ -d $dir ]] || { echo "sweep-models: $dir is not a folder (apt-get install assimp-testmodels)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rendered=0 refused=0 bad=0
while IFS= read -r -d '' file; do
  case ${file,,} in
    *.png | *.jpg | *.jpeg | *.tga | *.bmp | *.txt | *.glsl | *.bin | *.mtl | *.xml | *.dds | *.md) continue ;;
  esac
  for how in model mesh; do
    rm -rf "$work/run" && mkdir "$work/run"
    if [[ $how == model ]]; then
      target=$file
    else
      target=$work/run/s.scene
      printf 'camera { eye 0 0 -10 look_at 0 0 0 up 0 1 0 fov 40 }\nlight point { position 5 5 -5 color 1 1 1 }\nimage { width 16 height 12 }\nmesh { file "%s" }\n' "$file" >"$target"
    fi
    timeout -k 5 120 "$prt" render "$target" --width 16 --height 12 -q -o "$work/run/out.png" \
      >"$work/run/out" 2>"$work/run/err"
    code=$?
    case $code in
      0) rendered=$((rendered + 1)) ;;
      2) refused=$((refused + 1))
         [[ ${SWEEP_VERBOSE:-0} == 1 ]] &&
           echo "sweep-models: refused: $how $file: $(head -c 300 "$work/run/err" | tr '\n' ' ')" ;;
      *) bad=$((bad + 1))
         echo "sweep-models: $how $file: exit $code: $(head -c 300 "$work/run/err" | tr '\n' ' ')" ;;
    esac
  done
done < <(find "$dir" -type f -print0 | sort -z)
echo "sweep-models: $rendered rendered, $refused refused with a message, $bad crashed, hung or failed otherwise"
[[ $bad -eq 0 ]]
