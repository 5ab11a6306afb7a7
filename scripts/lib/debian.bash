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

# configured_debian_archive: prints the URI of the Debian archive this machine's apt is set up
# with (the `deb` source that carries the release's own suite, in /etc/apt/sources.list.d/*.sources
# or /etc/apt/sources.list); fails with a message if there is none. No host is named here.
configured_debian_archive() {
  local codename uri
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  uri=$(cat /etc/apt/sources.list.d/*.sources 2>/dev/null | awk -v c="$codename" '
    function flush() { if (types ~ /(^| )deb( |$)/ && (" " suites " ") ~ (" " c " ") && uri != "") { print uri; found = 1; exit } types = suites = uri = "" }
    /^[[:space:]]*$/ { flush(); next }
    /^Types:/ { sub(/^Types:[[:space:]]*/, ""); types = $0 }
    /^Suites:/ { sub(/^Suites:[[:space:]]*/, ""); suites = $0 }
    /^URIs:/ { uri = $2 }
    END { if (!found) flush() }')
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    uri=$(awk -v c="$codename" '$1 == "deb" { i = 2; if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ } if ($(i + 1) == c) { print $i; exit } }' \
      /etc/apt/sources.list)
  fi
  if [ -z "$uri" ]; then
    echo "no Debian archive for '$codename' is configured in /etc/apt; configure one, then run this again" >&2
    return 1
  fi
  echo "$uri"
}

# private_apt_source_state DIR SUITE: sets the array PRIVATE_APT to apt-get options that use a
# package state in DIR with deb-src SUITE main of the machine's configured Debian archive as the
# only source, and updates it.
private_apt_source_state() {
  local dir=$1 suite=$2 archive
  archive=$(configured_debian_archive) || exit 1
  mkdir -p "$dir/lists/partial"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $archive $suite main" > "$dir/src.list"
  PRIVATE_APT=(-o "Dir::Etc::SourceList=$dir/src.list" -o Dir::Etc::SourceParts=/dev/null -o "Dir::State::Lists=$dir/lists")
  apt-get "${PRIVATE_APT[@]}" update -qq
}
