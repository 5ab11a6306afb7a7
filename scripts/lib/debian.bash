# Helpers shared by the set-up scripts (sourced, not run): installing Debian packages that are
# missing, and an apt-get with a private state for fetching Debian source packages without
# touching /etc/apt.

# install_missing_packages LABEL PACKAGE...: installs those not installed (needs root then);
# does nothing when all are there.
install_missing_packages() {
  local label=$1 p
  shift
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -gt 0 ] || return 0
  echo "$label: installing ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then echo "$label: need root to install packages: ${missing[*]}" >&2; exit 1; fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# private_apt_source_state DIR SUITE: sets the array PRIVATE_APT to apt-get options that use a
# package state in DIR with Debian's deb-src SUITE main as the only source, and updates it.
private_apt_source_state() {
  local dir=$1 suite=$2
  mkdir -p "$dir/lists/partial"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" > "$dir/src.list"
  PRIVATE_APT=(-o "Dir::Etc::SourceList=$dir/src.list" -o Dir::Etc::SourceParts=/dev/null -o "Dir::State::Lists=$dir/lists")
  apt-get "${PRIVATE_APT[@]}" update -qq
}
