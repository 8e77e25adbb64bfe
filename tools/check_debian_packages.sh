#!/usr/bin/env bash
# Checks that the Debian packages named on the command line are installed (make deps). As root it
# installs the missing ones; otherwise it prints the one apt-get line to run and exits with 2.
#   tools/check_debian_packages.sh PACKAGE...
set -u
missing=""
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
  echo "deps: installing$missing"
  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing || exit 2
else
  echo "deps: missing Debian packages; run this line, then the make command again:"
  echo "sudo apt-get install -y$missing"
  exit 2
fi
