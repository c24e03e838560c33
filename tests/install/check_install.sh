#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, then builds and runs a
# downstream program with find_package(sillage) (sillage::sillage, and
# sillage::core alone) and with pkg-config, and the downstream project's own
# contractor tested with the installed contractor test kit
# (consumer/test_ctc_double.cpp, GoogleTest).
set -euo pipefail
build_dir=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"

# Exactly the public headers are installed (include/sillage/), none of src/.
source_dir=$(cd "$here/../.." && pwd)
diff <(cd "$source_dir/include" && find sillage -name '*.h' | sort) \
     <(cd "$work/prefix/include" && find sillage -name '*.h' | sort) \
  || { echo "install: the installed headers differ from include/sillage/"; exit 1; }

cmake -S "$here/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/consumer/consumer"
"$work/consumer/consumer_core"
"$work/consumer/ctc_double_test" > "$work/kit.log" 2>&1 || { cat "$work/kit.log"; exit 1; }

export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
g++ -O1 "$here/consumer/main.cpp" -o "$work/consumer_pc" $(pkg-config --cflags --libs sillage)
"$work/consumer_pc"
echo "install: find_package (umbrella and core) and pkg-config consumers and the installed test kit ok"
