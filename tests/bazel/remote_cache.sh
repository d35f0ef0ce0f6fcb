#!/usr/bin/env bash
# A build cache shared between machines: two Bazel builds of tests/bazel/workspace, in two workspace paths with
# their own hexc install and output base (two "machines": a's hexc is the one in $HEXC_INSTALLED_PREFIX when it is set,
# tests/package/prefix.sh, b's always BUILD installed into a prefix of its own), connected only through an HTTP remote
# cache that Debian's nginx serves with WebDAV PUT on a loopback port. The first build runs every hexc action and uploads the results;
# the second must run none (every one a remote cache hit) and write byte-identical files:
#   tests/bazel/remote_cache.sh BUILD
# Exits 77 (ctest's SKIP_RETURN_CODE) when bazel or nginx is not installed (Debian: bazel-bootstrap, nginx-light).
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v bazel > /dev/null || { echo "bazel: not installed (Debian package bazel-bootstrap); skipped"; exit 77; }
nginx=$(command -v nginx || echo /usr/sbin/nginx)
[ -x "$nginx" ] || { echo "nginx: not installed (Debian package nginx-light); skipped"; exit 77; }
build=$(realpath "$1")
work=$build/bazel_remote_cache
[ ! -e "$work" ] || chmod -R u+w "$work"  # Bazel leaves its outputs read-only
rm -rf "$work" && mkdir -p "$work"
source tests/bazel/common.sh
fail() { echo "remote cache: $*" >&2; exit 1; }

# The cache server: nginx in the foreground with its own prefix, config and logs, stopped by its pid. Its workers
# run as www-data when the test runs as root, so the folders they write are theirs.
ngx=$work/nginx
mkdir -p "$ngx"/{cache,temp}
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
cat > "$ngx/nginx.conf" <<CONF
daemon off;
worker_processes 1;
pid $ngx/nginx.pid;
error_log $ngx/error.log;
$([ "$(id -u)" -eq 0 ] && echo "user www-data;")
events {}
http {
  access_log $ngx/access.log;
  client_body_temp_path $ngx/temp;
  client_max_body_size 0;
  server {
    listen 127.0.0.1:$port;
    root $ngx/cache;
    location / {
      dav_methods PUT;
      create_full_put_path on;
    }
  }
}
CONF
[ "$(id -u)" -ne 0 ] || chown -R www-data "$ngx/cache" "$ngx/temp"
"$nginx" -p "$ngx" -c "$ngx/nginx.conf" -e "$ngx/error.log" &
server=$!
a=$work/machine_a/src/game b=$work/machine_b/home/ci/checkout
# A Bazel server that has already gone (idle for a minute while the other machine built) fails its shutdown: the
# cache server is stopped all the same, or it would keep the test's output open and ctest waiting.
trap 'in_bazel "$a" "$work/machine_a/root" shutdown || true; in_bazel "$b" "$work/machine_b/root" shutdown || true
  kill $server; wait $server' EXIT
for _ in $(seq 50); do (: < /dev/tcp/127.0.0.1/$port) 2> /dev/null && break || sleep 0.1; done
(: < /dev/tcp/127.0.0.1/$port) 2> /dev/null || { cat "$ngx/error.log"; fail "nginx did not start"; }

for m in a b; do
  mkdir -p "$work/machine_$m" "$(dirname "${!m}")"
done
hexc_a=$(tests/package/prefix.sh "$build" "$work/machine_a/hexc")
hexc_b=$(HEXC_INSTALLED_PREFIX= tests/package/prefix.sh "$build" "$work/machine_b/hexc")
workspace "$a" "$hexc_a"
workspace "$b" "$hexc_b"
cache=--remote_cache=http://127.0.0.1:$port
build_all "$a" "$work/machine_a/root" "$work/a.json" "$cache" > "$work/log" 2>&1 || { cat "$work/log"; fail "machine a's build failed"; }
ran=$(python3 tests/bazel/hexc_actions.py "$work/a.json" ran)
[ "$ran" = "crate gravel rock slate yard" ] || { cat "$work/log"; fail "machine a ran hexc for [$ran]"; }
uploads=$(grep -c '"PUT /cas/' "$ngx/access.log" || true)
echo "ok: machine a ran hexc for [$ran] and uploaded $uploads files"

build_all "$b" "$work/machine_b/root" "$work/b.json" "$cache" > "$work/log" 2>&1 || { cat "$work/log"; fail "machine b's build failed"; }
ran=$(python3 tests/bazel/hexc_actions.py "$work/b.json" ran) cached=$(python3 tests/bazel/hexc_actions.py "$work/b.json" cached)
[ -z "$ran" ] && [ "$cached" = "crate gravel rock slate yard" ] ||
  { cat "$work/log"; fail "machine b ran hexc for [$ran]; the cache served [$cached]"; }
grep -o "[0-9]* remote cache hit" "$work/log" || fail "Bazel reported no remote cache hit"
files=0
for f in "$a"/bazel-bin/*; do
  [ -f "$f" ] || continue
  cmp "$f" "$b/bazel-bin/${f##*/}" || fail "bazel-bin/${f##*/} differs between the machines"
  files=$((files + 1))
done
[ "$(ls "$a/bazel-bin")" = "$(ls "$b/bazel-bin")" ] || fail "the machines' bazel-bin hold different files"
echo "ok: machine b ran no hexc action, the cache served [$cached]; its $files files are byte-identical to machine a's"
