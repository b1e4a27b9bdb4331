#!/usr/bin/env bash
# Puts the nanopb runtime sources (pb.h, pb_common, pb_encode, pb_decode) of the Debian package that
# is installed into DEST. libubii compiles them itself: Debian's prebuilt runtime is built with
# PB_ENABLE_MALLOC, and the embedded, fuzzing and cross builds need their own compile.
#
# The deb-src entry is derived from this machine's own apt sources, in a private apt state folder,
# so nothing under /etc is changed and no host is named here.
set -euo pipefail

dest=${1:?usage: fetch-nanopb-source.sh DEST}
version=$(dpkg-query -W -f='${Version}' libnanopb-dev 2>/dev/null) || {
  echo "fetch-nanopb-source: libnanopb-dev is not installed (run scripts/bootstrap.sh)" >&2
  exit 1
}
upstream=${version%-*}
[ -f "$dest/pb_decode.c" ] && [ "$(cat "$dest/VERSION" 2>/dev/null)" = "$version" ] && exit 0

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/parts" "$work/lists/partial" "$work/cache/archives/partial" "$work/out"

found_sources=0
for sources in /etc/apt/sources.list.d/*.sources; do
  [ -e "$sources" ] || continue
  sed 's/^Types:.*\bdeb\b.*$/Types: deb-src/' "$sources" > "$work/parts/$(basename "$sources")"
  found_sources=1
done
if [ -f /etc/apt/sources.list ]; then
  sed -n 's/^deb \(.*\)$/deb-src \1/p' /etc/apt/sources.list > "$work/parts/from-sources-list.list"
  [ -s "$work/parts/from-sources-list.list" ] && found_sources=1
fi
[ "$found_sources" = 1 ] || { echo "fetch-nanopb-source: no apt sources found" >&2; exit 1; }

apt_opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work/parts"
          -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache" -o "APT::Sandbox::User=root")
apt-get "${apt_opts[@]}" update -qq >/dev/null
(cd "$work/out" && apt-get "${apt_opts[@]}" source --download-only "nanopb=$version" >/dev/null)

tarball=$(ls "$work/out"/nanopb_"$upstream".orig.tar.* | head -n 1)
tar -xf "$tarball" -C "$work/out"
mkdir -p "$dest"
for file in pb.h pb_common.h pb_common.c pb_encode.h pb_encode.c pb_decode.h pb_decode.c LICENSE.txt; do
  cp "$work/out/nanopb-$upstream/$file" "$dest/"
done
echo "$version" > "$dest/VERSION"
echo "fetch-nanopb-source: nanopb $version runtime sources in $dest"
