#!/usr/bin/env bash
# The sweep over CGAL's data set (doc/robustness.md): runs `diffuv param` on
# every mesh, one at a time, and prints a markdown table of the outcomes.
#
# Usage: scripts/sweep.sh [--build DIR] [--timeout SECONDS] [--keep DIR] [--tsv FILE] [--args "OPTIONS"] [MESH...]
#   --build DIR      build folder (default: build): the tool is DIR/src/diffuv,
#                    the meshes DIR/data/meshes/*
#   --timeout S      a run longer than S seconds is a hang (default: 120)
#   --keep DIR       keep every run's stdout, stderr and output folder in DIR
#   --tsv FILE       also write the rows as tab-separated values
#   --args "OPTIONS" more options for `diffuv param`, e.g. "--distance graph"
#   MESH...          only these mesh files (default: all of DIR/data/meshes)
#
# Outcomes, the same rules as the CTest label `sweep` (cmake/sweep_mesh.cmake):
#   result        exit 0, every output file there and not empty, no NaN in the uv table
#   partial       the same, with a `diffuv: warning:` (patches left out)
#   error         exit 1 and one `diffuv: error: <mesh>[:<line>]: <reason>` line, no output folder
#   CRASH         a signal, an internal error (exit 4), "terminate called", a sanitizer report
#   HANG          still running after the timeout
#   BAD           anything else (unclear message, files left behind, missing or NaN outputs)
# The exit code is 0 if no mesh had a CRASH, HANG or BAD outcome, else 1.
set -uo pipefail

build=build
limit=120
keep=
tsv=
args=
meshes=()
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --timeout) limit=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    --args) args=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set /p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "sweep.sh: unknown option $1" >&2; exit 2 ;;
    *) meshes+=("$1"); shift ;;
  esac
done
tool="$build/src/diffuv"
[ -x "$tool" ] || { echo "sweep.sh: no tool at $tool (build it first)" >&2; exit 2; }
if [ ${#meshes[@]} -eq 0 ]; then
  for m in "$build"/data/meshes/*; do [ -f "$m" ] && meshes+=("$m"); done
fi
[ ${#meshes[@]} -gt 0 ] || { echo "sweep.sh: no meshes in $build/data/meshes" >&2; exit 2; }

work=${keep:-$(mktemp -d)}
mkdir -p "$work"
[ -n "$keep" ] || trap 'rm -rf "$work"' EXIT

# Vertex and polygon counts from the file's header (OFF, PLY, STL), for the
# meshes the tool refuses; "?" where the header does not tell.
header_counts() {
  case ${1,,} in
    *.off)
      # OFF [V F E], comments (#) and blank lines allowed before the counts.
      awk '{ sub(/#.*/, "") } NF { for(i = 1; i <= NF; ++i) t[++n] = $i } n >= 4 { exit }
           END { s = (t[1] ~ /OFF$/) ? 2 : 1; if(t[1] ~ /^[0-9]/) s = 1; print t[s] " " t[s+1] }' "$1" ;;
    *.ply)
      awk '/^element vertex/ { v = $3 } /^element face/ { f = $3 } /^end_header/ { exit }
           END { print (v == "" ? "?" : v) " " (f == "" ? "?" : f) }' "$1" ;;
    *.stl)
      if head -c 5 "$1" | grep -q solid && grep -q -m1 facet "$1"; then
        echo "? $(grep -c endfacet "$1")"
      else
        echo "? $(od -An -tu4 -j80 -N4 "$1" | tr -d ' ')"
      fi ;;
    *) echo "? ?" ;;
  esac
}

ok=0 partial=0 errors=0 crashes=0 hangs=0 bad=0
rows=()
bad_list=()
for mesh in "${meshes[@]}"; do
  name=$(basename "$mesh")
  stem=${name%.*}
  log="$work/$name"
  out="$log.out"
  rm -rf "$out"
  start=$(date +%s.%N)
  timeout --kill-after=10 "$limit" "$tool" param "$mesh" $args -o "$out" >"$log.stdout" 2>"$log.stderr" </dev/null
  rc=$?
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  seconds=$(printf '%.1f' "$seconds")

  read -r vertices faces < <(header_counts "$mesh")
  summary=$(head -n1 "$log.stdout")
  if [[ $summary =~ :\ ([0-9]+)\ vertices,\ ([0-9]+)\ faces ]]; then
    vertices=${BASH_REMATCH[1]} faces=${BASH_REMATCH[2]}
  fi
  stderr_text=$(cat "$log.stderr")
  error_lines=$(grep -c '^diffuv: error: ' "$log.stderr")
  warning=$(grep -m1 '^diffuv: warning: ' "$log.stderr" | sed 's/^diffuv: warning: //')

  outcome= detail=
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    outcome=HANG detail="still running after ${limit} s"
  elif [ $rc -gt 128 ] || [ $rc -eq 4 ] ||
       grep -q -E 'terminate called|Sanitizer|runtime error:|Assertion|Segmentation|internal error|CGAL ERROR|precondition' "$log.stderr"; then
    outcome=CRASH detail="exit $rc: $(echo "$stderr_text" | grep -v '^$' | tail -n1)"
  elif [ $rc -eq 0 ]; then
    missing=
    for ending in .obj .mtl .checker.png .uv.csv .patches.txt .png; do
      [ -s "$out/$stem$ending" ] || missing+=" $stem$ending"
    done
    if [ -n "$missing" ]; then
      outcome=BAD detail="exit 0 but missing or empty:$missing"
    elif grep -q -i -E "nan|inf" "$out/$stem.uv.csv"; then
      outcome=BAD detail="NaN or infinity in $stem.uv.csv"
    elif [ -n "$(grep -v -E '^diffuv: warning: ' "$log.stderr")" ]; then
      outcome=BAD detail="exit 0 with other text on stderr: $(grep -v -E '^diffuv: warning: ' "$log.stderr" | head -n1)"
    else
      patches=$(grep -m1 -o -E '^[0-9]+ patch(es)?' "$log.stdout" || true)
      [ -n "$patches" ] || patches=$(sed -n 2p "$log.stdout" | cut -c1-60)
      # What reading repaired (issue #21), after the patches.
      repaired=$(grep -m1 '^repaired: ' "$log.stdout" | sed 's/ (--strict-input turns repairs off)//' || true)
      [ -z "$repaired" ] || patches+="; $repaired"
      if [ -n "$warning" ]; then
        outcome=partial detail="$patches; warning: $warning"
      else
        outcome=result detail="$patches"
      fi
    fi
  elif [ $rc -eq 1 ]; then
    line=$(grep -m1 '^diffuv: error: ' "$log.stderr")
    # The mesh named, perhaps with a line number: diffuv: error: <mesh>[:<line>]: <reason>
    reason=${line#"diffuv: error: $mesh"}
    [[ $reason =~ ^:[0-9]+: ]] && reason=${reason#:*:} || reason=${reason#:}
    if [ "$error_lines" -ne 1 ] || [ "$reason" = "$line" ] || [ "${reason:0:1}" != " " ]; then
      outcome=BAD detail="exit 1 without a 'diffuv: error: $name: ...' line: $(echo "$stderr_text" | tail -n1)"
    elif [ -e "$out" ]; then
      outcome=BAD detail="exit 1 but the output folder was left behind"
    else
      outcome=error detail=${reason# }
    fi
  else
    outcome=BAD detail="exit $rc: $(echo "$stderr_text" | tail -n1)"
  fi

  case $outcome in
    result) ok=$((ok + 1)) ;;
    partial) partial=$((partial + 1)) ;;
    error) errors=$((errors + 1)) ;;
    CRASH) crashes=$((crashes + 1)); bad_list+=("$name") ;;
    HANG) hangs=$((hangs + 1)); bad_list+=("$name") ;;
    *) bad=$((bad + 1)); bad_list+=("$name") ;;
  esac
  detail=${detail//|/\\|}
  rows+=("| $name | $vertices | $faces | $outcome | $seconds | $detail |")
  [ -z "$tsv" ] || printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$vertices" "$faces" "$outcome" "$seconds" "$detail" >>"$tsv"
  [ -n "$keep" ] || rm -rf "$out"
  echo "$name: $outcome ($seconds s)" >&2
done

echo "${#meshes[@]} meshes: $ok results, $partial partial results, $errors clear errors, $crashes crashes, $hangs hangs, $bad other bad outcomes"
echo
echo "| mesh | vertices | faces | outcome | seconds | patches or message |"
echo "|---|---:|---:|---|---:|---|"
printf '%s\n' "${rows[@]}"
if [ ${#bad_list[@]} -gt 0 ]; then
  echo
  echo "bad outcomes: ${bad_list[*]}"
  exit 1
fi
