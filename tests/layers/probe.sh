#!/bin/sh
# One layer probe: compiles FILE with the include directories a module's sources get and checks
# the outcome. `ok`: it must compile. `refused HEADER`: it must fail, because HEADER is not found
# (and for no other reason).
#   probe.sh ok|refused HEADER -- COMPILER FLAGS... FILE
set -u
expect=$1
shift
header=""
if [ "$expect" = refused ]; then
  header=$1
  shift
fi
[ "$1" = "--" ] && shift
out=$("$@" 2>&1)
status=$?
if [ "$expect" = ok ]; then
  [ $status -eq 0 ] && exit 0
  echo "expected to compile, but:"
  echo "$out"
  exit 1
fi
if [ $status -eq 0 ]; then
  echo "compiled, but $header is in a higher layer and must not be found"
  exit 1
fi
if echo "$out" | grep -q "$header: No such file or directory"; then
  echo "refused as it must be: $header not found"
  exit 0
fi
echo "failed, but not because $header was not found:"
echo "$out"
exit 1
