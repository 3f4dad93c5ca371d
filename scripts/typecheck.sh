#!/usr/bin/env bash
# mypy over the cnlmc package: the one command that type-checks everything.
#
#   scripts/typecheck.sh                 # the whole package (compiler/ strict, backends/ checked)
#   scripts/typecheck.sh compiler/syntax.py backends/glsl   # just these files or folders
#
# pyproject.toml maps folders to the package (compiler/ -> cnlmc, backends/ -> cnlmc.backends,
# grammar/, stdlib/); the editable install reaches them through an import hook that mypy
# cannot follow. So this mirrors that mapping as symbolic links under build/typecheck/cnlmc
# (made again each run, so new files are seen; nothing is installed), runs mypy there with
# the settings in pyproject.toml [tool.mypy], and prints the real paths in its report.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
tree="build/typecheck/cnlmc"
mypy="${MYPY:-$root/.venv/bin/mypy}"

link_tree() {
    mkdir -p "$tree"
    local entry name
    for entry in compiler/* backends grammar stdlib; do
        name="$(basename "$entry")"
        [[ "$entry" == compiler/* && ( "$name" == __pycache__ || "$name" == backends ) ]] && continue
        [[ "$entry" == compiler/* ]] || name="$entry"
        [[ -L "$tree/$name" ]] || ln -s "../../../$entry" "$tree/$name"
    done
    for entry in "$tree"/*; do  # a link to a file that was deleted or moved
        [[ -e "$entry" ]] || rm -f "$entry"
    done
}

to_tree() {  # a real path -> the same file or folder in the link tree
    case "$1" in
        compiler | compiler/) find "$tree" -mindepth 1 -maxdepth 1 \( -name "*.py" -o -type d -o -xtype d \) \
            ! -name backends ! -name grammar ! -name stdlib | sort ;;
        compiler/*) echo "$tree/${1#compiler/}" ;;
        backends* | grammar* | stdlib*) echo "$tree/$1" ;;
        *) echo "$1" ;;
    esac
}

link_tree
args=()
for arg in "$@"; do
    if [[ "$arg" == -* ]]; then args+=("$arg"); else mapfile -t -O "${#args[@]}" args < <(to_tree "$arg"); fi
done
set +e
"$mypy" "${args[@]}" 2>&1 | sed -e "s#$tree/\(backends\|grammar\|stdlib\)\([/:]\)#\1\2#g" -e "s#$tree/#compiler/#g"
exit "${PIPESTATUS[0]}"
