#!/usr/bin/env bash
# A virtual desktop for `rt view` inside the container: display :1 (Xvfb), a window manager, a VNC
# server on it, and noVNC serving that to a browser on port 6080 (open
# http://localhost:6080/vnc.html, press Connect). Started by devcontainer.json; safe to re-run.
set -euo pipefail
if ! pgrep -x Xvfb > /dev/null; then
  Xvfb :1 -screen 0 1280x800x24 -nolisten tcp > /tmp/xvfb.log 2>&1 &
  for _ in $(seq 50); do [ -e /tmp/.X11-unix/X1 ] && break; sleep 0.1; done
fi
export DISPLAY=:1
pgrep -x fluxbox > /dev/null || (fluxbox > /tmp/fluxbox.log 2>&1 &)
pgrep -x x11vnc > /dev/null ||
  x11vnc -display :1 -forever -shared -nopw -localhost -rfbport 5900 -bg -o /tmp/x11vnc.log > /dev/null
pgrep -f "websockify.*6080" > /dev/null ||
  (websockify --web /usr/share/novnc 6080 127.0.0.1:5900 > /tmp/novnc.log 2>&1 &)
echo "desktop: DISPLAY=:1; see it at http://localhost:6080/vnc.html"
