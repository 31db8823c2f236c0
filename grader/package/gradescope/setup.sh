#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu 22.04). It
# installs only what grading needs (rt-grade/packages.txt, names from target_packages.txt that
# exist on Debian 12 and Ubuntu 22.04 alike); nothing is compiled here: rt-grade, the judges and
# the framework were built where the package was made.
set -euo pipefail
root=${RT_AUTOGRADER_ROOT:-/autograder}
bundle=$root/source/rt-grade
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
xargs -a "$bundle/packages.txt" apt-get install -y -qq --no-install-recommends > /dev/null
# Student code runs as nobody: it may read the public tree and the runtime, never the private
# folder (solutions, hidden tests, references, the secret of the unseen views).
chmod 711 "$root/source"
chmod -R go-w,go+rX "$bundle"
chmod -R go-rwx "$bundle/cache/private"
# Fails the image build now, not the first student's grading, if a library does not load.
"$bundle/bin/rt-grade" --help > /dev/null
echo "setup.sh: grading bundle ready ($(du -sh "$bundle" | cut -f1))"
