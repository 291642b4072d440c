#!/usr/bin/env bash
# Repository.NoPathOutsideTheRepository: no document, build file or source that git tracks,
# outside tests/, refers to a path outside the repository. Fails, printing FILE:LINE, on
#   (a) a mention of ../shared or of shared/DESIGN, shared/TOOLCHAIN, shared/STYLE, and
#   (b) a relative path with a `..` component that leaves the repository when resolved from
#       the file's folder (from the repository root after ${PROJECT_SOURCE_DIR} or
#       ${CMAKE_SOURCE_DIR}), or that names nothing from the file's folder and leaves the
#       repository from its root (a path written relative to the root).
# Binary files and images are skipped. Without git or a .git folder it skips (exit 77).
# Usage: outside_paths_test.sh [REPOSITORY_ROOT]
# shellcheck disable=SC2016  # '${PROJECT_SOURCE_DIR}' etc. are matched literally, on purpose
set -uo pipefail
set -f  # no globbing: tokens such as shaders/*.glsl stay as written

readonly kSkip=77
root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
if ! command -v git >/dev/null 2>&1; then
  echo "SKIP: git is not installed; cannot list the tracked files"
  exit $kSkip
fi
if [ ! -e "$root/.git" ]; then
  echo "SKIP: $root has no .git (not a git checkout); cannot list the tracked files"
  exit $kSkip
fi
cd "$root" || exit 1
if ! listing=$(git -C "$root" ls-files -z 2>&1 | tr '\0' '\n'); then
  echo "SKIP: git ls-files failed in $root: $(printf '%s' "$listing" | head -n 1)"
  exit $kSkip
fi

files=()
while IFS= read -r f; do
  case "$f" in
    '' | tests/*) continue ;;
    *.png | *.jpg | *.jpeg | *.gif | *.bmp | *.tga | *.exr | *.hdr | *.ktx | *.dds) continue ;;
    *.olpak | *.glb | *.bin | *.pk3 | *.zip | *.gz | *.xz | *.pdf) continue ;;
  esac
  [ -f "$f" ] && files+=("$f")
done <<<"$listing"
if [ ${#files[@]} -eq 0 ]; then
  echo "FAIL: git lists no file to check in $root"
  exit 1
fi

problems=0
report() {  # FILE:LINE: what (the words are joined by spaces)
  echo "$*"
  problems=$((problems + 1))
}

# (a) The design documents' former home beside the repository.
while IFS= read -r hit; do
  report "$hit"
done < <(grep -n -I -H -E '\.\./shared|shared/(DESIGN|TOOLCHAIN|STYLE)' -- "${files[@]}")

# Normalises `path` (components separated by /) under `base` (a folder relative to the
# repository root, "" for the root). Prints the normalised path; returns 1 when `..` climbs
# above the root.
resolve() {
  local base=$1 path=$2 part
  local -a stack=()
  local IFS=/
  for part in $base $path; do
    case "$part" in
      '' | .) ;;
      ..)
        [ ${#stack[@]} -eq 0 ] && return 1
        unset 'stack[${#stack[@]}-1]'
        ;;
      *) stack+=("$part") ;;
    esac
  done
  printf '%s' "${stack[*]}"
}

# The part of a normalised path before its first wildcard or placeholder, which must exist.
exists_prefix() {
  local path=$1 prefix="" part
  local IFS=/
  for part in $path; do
    case "$part" in *'*'* | *'?'* | *'['* | *@* | *'$'* | *'<'* | *'>'*) break ;; esac
    prefix=${prefix:+$prefix/}$part
  done
  [ -z "$prefix" ] || [ -e "$prefix" ]
}

# (b) Relative paths with `..` that leave the repository. Tokens are runs of characters that
# can be part of a path; CMake's and the shell's folder variables become markers first.
readonly delimiters=$' \t"\'`()<>[],;:=|&!?#{}'
while IFS= read -r hit; do
  file=${hit%%:*}
  rest=${hit#*:}
  line=${rest%%:*}
  text=${rest#*:}
  folder=$(dirname "$file")
  [ "$folder" = . ] && folder=""
  text=${text//'${PROJECT_SOURCE_DIR}'/ @ROOT@}
  text=${text//'${CMAKE_SOURCE_DIR}'/ @ROOT@}
  text=${text//'${CMAKE_CURRENT_SOURCE_DIR}'/ @HERE@}
  text=${text//'${CMAKE_CURRENT_LIST_DIR}'/ @HERE@}
  text=${text//'$(dirname "${BASH_SOURCE[0]}")'/ @HERE@}
  text=${text//'$(dirname "$0")'/ @HERE@}
  for c in $(seq 0 $((${#delimiters} - 1))); do text=${text//"${delimiters:c:1}"/ }; done
  for token in $text; do
    case "$token" in
      *://*) continue ;;                             # a URL
      ..* | */..* | @ROOT@* | @HERE@*) ;;            # a candidate
      *) continue ;;
    esac
    case "/$token/" in */../*) ;; *) continue ;; esac  # a `..` component, not `...` or `0..5`
    base=$folder
    path=$token
    case "$token" in
      @ROOT@*) base="" path=${token#@ROOT@} ;;
      @HERE@*) path=${token#@HERE@} ;;
      /*) continue ;;                                # absolute: not relative to anything here
      '~'*) continue ;;
    esac
    shown=${token/#@ROOT@/<repository root>}
    shown=${shown/#@HERE@/<this folder>}
    if ! resolved=$(resolve "$base" "$path"); then
      where=${base:+$base/}
      report "$file:$line: '$shown' leaves the repository" \
        "(resolved from ${where:-the repository root})"
    elif [ -n "$base" ] && [ "$base" = "$folder" ] && ! exists_prefix "$resolved" &&
      ! resolve "" "$path" >/dev/null; then
      report "$file:$line: '$shown' names nothing from $folder/" \
        "and leaves the repository from its root"
    fi
  done
done < <(grep -n -I -H -E '(\.\./|/\.\.)' -- "${files[@]}")

if [ $problems -gt 0 ]; then
  echo "FAIL: $problems reference(s) to paths outside the repository in the tracked files above" \
    "(tests/ excluded); point them into the repository, e.g. at docs/"
  exit 1
fi
echo "OK: ${#files[@]} tracked files (tests/ excluded) refer to no path outside the repository"
exit 0
