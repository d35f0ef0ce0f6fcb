# What the Bazel tests share (sourced): the workspace they build and how they run Bazel.

# Lays out tests/bazel/workspace in DIR, against hexc installed in PREFIX, with the repository's example textures.
workspace() {  # DIR PREFIX
  cp -r tests/bazel/workspace "$1"
  sed -i "s|/opt/hexc|$2|" "$1/WORKSPACE"
  mkdir -p "$1/materials/textures"
  cp materials/rock.json "$1/materials/"
  cp materials/textures/{rock_albedo,rock_normal,rock_roughness,tiles_albedo}.png "$1/materials/textures/"
  cp materials/textures/rock_albedo.png "$1/materials/textures/gravel_albedo.png"
  cp materials/textures/rock_roughness.png "$1/materials/textures/crate_roughness.png"
}

# Bazel in workspace WS with its output base under ROOT: only Debian's system bazelrc applies, not a user's. One
# server per ROOT (a JVM start costs seconds per command), stopped by `in_bazel WS ROOT shutdown` when the test ends,
# or after a minute of idleness if it is killed. linux-sandbox explicitly: a sandbox that cannot start fails the
# build instead of falling back to none; a strict action environment, so that no variable of this shell's is in an
# action's key.
in_bazel() {  # WS ROOT COMMAND [ARGS...]
  local ws=$1 root=$2 command=$3
  shift 3
  (cd "$ws" && bazel --nohome_rc --noworkspace_rc --output_user_root="$root" --max_idle_secs=60 "$command" "$@")
}
# Builds every target of WS, with the execution log (the actions that ran or came from a remote cache, not those the
# local action cache had) in LOG; more options may follow.
build_all() {  # WS ROOT LOG [OPTIONS...]
  local ws=$1 root=$2 log=$3
  shift 3
  in_bazel "$ws" "$root" build --nosandbox_debug --spawn_strategy=linux-sandbox --incompatible_strict_action_env \
    --execution_log_json_file="$log" "$@" //...
}
