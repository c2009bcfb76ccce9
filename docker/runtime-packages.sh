#!/usr/bin/env bash
# Prints, one per line and sorted, the Debian packages that hold the shared libraries the given
# executables load (as ldd resolves them), so that the image's runtime stage installs exactly
# those and nothing else. Run in the build stage, on the binaries it built.
# Exit 1, naming it, on a library ldd cannot find or that no installed package owns.
#
# usage: docker/runtime-packages.sh EXECUTABLE...
set -euo pipefail

[[ $# -gt 0 ]] || { echo "usage: $0 EXECUTABLE..." >&2; exit 1; }

# dpkg records each file under the path its package ships it at, which on a merged-/usr system
# may be /lib/... or /usr/lib/... whatever ldd printed: ask for both spellings.
owner() {
    local path=$1 candidate found
    for candidate in "$path" "/usr$path" "${path#/usr}"; do
        # "package:arch: /path" (or "package-a, package-b: /path" for a shared directory)
        found=$(dpkg-query --search "$candidate" 2> /dev/null) || continue
        found=${found%%$'\n'*}
        found=${found%%[:,]*}
        echo "$found"
        return 0
    done
    return 1
}

libraries=$(for exe in "$@"; do ldd "$exe"; done)
if grep -q 'not found' <<< "$libraries"; then
    echo "runtime-packages: ldd cannot resolve: $(grep 'not found' <<< "$libraries" | sort -u)" >&2
    exit 1
fi

# Lines "libX.so.N => /path (0x...)"; the vDSO and the dynamic loader (libc6) have no "=> /path".
awk '$2 == "=>" && $3 ~ /^\// { print $3 }' <<< "$libraries" | sort -u | while read -r path; do
    if ! package=$(owner "$path") || [[ -z $package ]]; then
        echo "runtime-packages: no installed package owns $path" >&2
        exit 1
    fi
    echo "$package"
done | sort -u
