# The browser tests' driver (docs/viewer.md#lecture-demos-in-a-browser): node and puppeteer-core in
# tools/web. Sets NODE_EXE, or WEB_SKIPPED to the one line a test prints before it returns.
find_program(NODE_EXE NAMES node nodejs)
set(WEB_SKIPPED "")
if(NOT NODE_EXE)
  set(WEB_SKIPPED "SKIPPED: node is missing (scripts/install-deps.sh installs nodejs and npm)")
elseif(NOT EXISTS ${SOURCE}/tools/web/node_modules/puppeteer-core)
  set(WEB_SKIPPED
      "SKIPPED: puppeteer-core is missing (scripts/install-deps.sh runs npm ci in tools/web)")
endif()
