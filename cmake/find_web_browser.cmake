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

# render_pages(ARGS...): tools/web/render_pages.js with those arguments, its output printed.
# When it skipped (no WebGL2 in the browser) the calling script ends there, as a macro's return()
# does; otherwise render_pages_rc holds its exit status and render_pages_out its output.
macro(render_pages)
  execute_process(COMMAND ${NODE_EXE} ${SOURCE}/tools/web/render_pages.js ${ARGN}
                  RESULT_VARIABLE render_pages_rc OUTPUT_VARIABLE render_pages_out
                  ERROR_VARIABLE render_pages_out)
  message("${render_pages_out}")
  if(render_pages_out MATCHES "SKIPPED: ")
    return()
  endif()
endmacro()

# web_check_start(FOLDERS...): a web check's first step after including this file. Without a
# browser it prints the one line and ends the calling script; otherwise OUT starts empty, with
# FOLDERS made.
macro(web_check_start)
  if(WEB_SKIPPED)
    message("${WEB_SKIPPED}")
    return()
  endif()
  file(REMOVE_RECURSE ${OUT})
  set(web_check_folders ${ARGN})
  if(web_check_folders)
    file(MAKE_DIRECTORY ${web_check_folders})
  endif()
endmacro()
