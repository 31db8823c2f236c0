# Included by framework/CMakeLists.txt, so paths are relative to framework/: the tests that run
# `rt` itself (determinism, one-line errors, the GPU from the command line, rt fmt, the gallery
# page, the viewer under Xvfb) and the checks over the framework's tree.
# Command-line behaviour of `rt`: determinism across thread counts, clean errors.
set(rt_cli_scene ${PROJECT_SOURCE_DIR}/stages/02-intersections/scenes/mesh_normals.json)
add_test(NAME Render.ThreadCountIsBitIdentical
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSCENE=${rt_cli_scene}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/determinism
          -P ${PROJECT_SOURCE_DIR}/cmake/check_thread_determinism.cmake)
set_tests_properties(Render.ThreadCountIsBitIdentical PROPERTIES LABELS "render")
# The same for a shaded scene with shadows, reflection and refraction.
add_test(NAME Render.ShadedThreadCountIsBitIdentical
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt>
          -DSCENE=${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json
          -DOUT=${PROJECT_BINARY_DIR}/test-output/determinism-shaded
          -P ${PROJECT_SOURCE_DIR}/cmake/check_thread_determinism.cmake)
set_tests_properties(Render.ShadedThreadCountIsBitIdentical PROPERTIES LABELS "render")

function(rt_cli_error_test name expect)
  add_test(NAME Cli.${name}
    COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:rt>;${ARGN}" "-DEXPECT=${expect}"
            -P ${PROJECT_SOURCE_DIR}/cmake/check_cli_error.cmake)
  set_tests_properties(Cli.${name} PROPERTIES LABELS "cli")
endfunction()
set(bad ${CMAKE_CURRENT_SOURCE_DIR}/tests/bad_scenes)
rt_cli_error_test(MissingSceneFile "no-such-scene.json" render no-such-scene.json -o ${PROJECT_BINARY_DIR}/x.png)
rt_cli_error_test(UnknownFlag "--bogus" render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.png --bogus)
rt_cli_error_test(ZeroThreads "--threads" render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.png --threads 0)
rt_cli_error_test(HugeWidth "--width" render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.png --width 100000)
rt_cli_error_test(BadOutputExtension "x.bmpx" render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.bmpx)
# Instances (docs/scene-format.md#transforms-and-instances) on the GPU are drawn from a world-space
# copy, which cannot keep an unevenly scaled sphere or show the CPU's primitives: one line each.
# (Scenes without a BVH, so that a starter tree's stubbed build_bvh says nothing first.)
rt_cli_error_test(GpuInstanceOfAStretchedSphere "a sphere of an instance is scaled unevenly"
                  render ${CMAKE_CURRENT_SOURCE_DIR}/tests/scenes/stretched_sphere.json --gpu
                  -o ${PROJECT_BINARY_DIR}/x.png)
rt_cli_error_test(ExportOfInstancesRefusesThePrimitiveView "shows primitives and the tree"
                  export-web ${CMAKE_CURRENT_SOURCE_DIR}/tests/scenes/rotated_box.json
                  --mode primitive -o ${PROJECT_BINARY_DIR}/x.html)
set(rt_instance_scene ${CMAKE_CURRENT_SOURCE_DIR}/tests/scenes/instance_field.json)
add_test(NAME Render.InstancesThreadCountIsBitIdentical
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSCENE=${rt_instance_scene}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/determinism-instances
          -P ${PROJECT_SOURCE_DIR}/cmake/check_thread_determinism.cmake)
set_tests_properties(Render.InstancesThreadCountIsBitIdentical PROPERTIES LABELS "render")
rt_cli_error_test(OutputFolderMissing "no/such/dir/x.png" render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/no/such/dir/x.png)
# Stage 09 from the command line: a small GPU render says which context it used; what the port
# cannot draw is one line.
add_test(NAME Cli.GpuRenderNamesItsContext
  COMMAND $<TARGET_FILE:rt> render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/cli-gpu-context.png
          --gpu --width 32 --height 24)
set_tests_properties(Cli.GpuRenderNamesItsContext PROPERTIES LABELS "cli;gpu"
  PASS_REGULAR_EXPRESSION "gpu: egl \\([a-z]+\\): .*GPU \\(egl\\)")
rt_cli_error_test(GpuBvhVisitsWithoutBvh "draws the scene's BVH, and it has none"
                  render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.png --gpu --mode bvh_visits)
rt_cli_error_test(UberWithoutGpu "--uber chooses the GPU shader; add --gpu"
                  render ${rt_cli_scene} -o ${PROJECT_BINARY_DIR}/x.png --uber)
# The third context: a GLFW window under Xvfb renders the image EGL renders (byte for byte).
add_test(NAME Framework.GpuWindowMatchesEgl
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt>
          -DSCENE=${PROJECT_SOURCE_DIR}/stages/07-textures/scenes/textured_whitted.json
          -DOUT=${PROJECT_BINARY_DIR}/test-output/gpu-window
          -P ${PROJECT_SOURCE_DIR}/cmake/check_gpu_window.cmake)
# RESOURCE_LOCK xvfb: two `xvfb-run -a` starting at once can pick the same display number.
set_tests_properties(Framework.GpuWindowMatchesEgl PROPERTIES LABELS "framework;gpu" TIMEOUT 300
  RESOURCE_LOCK xvfb)
rt_skip_pattern(Framework.GpuWindowMatchesEgl "SKIPPED: xvfb-run is missing")
add_test(NAME Cli.MalformedScenesGiveOneLineErrors
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DDIR=${bad}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/bad-scenes
          -P ${PROJECT_SOURCE_DIR}/cmake/check_bad_scenes.cmake)
set_tests_properties(Cli.MalformedScenesGiveOneLineErrors PROPERTIES LABELS "cli;scene")
# rt compare of a graded reference image, without threshold options, uses the grader's
# thresholds (stage 10's 8x8 blocks and 1.5%); with one, only what was given.
set(soft_shadows ${PROJECT_SOURCE_DIR}/reference_images/10-sampling/soft_shadows.png)
add_test(NAME Cli.CompareUsesTheGradersThresholds
  COMMAND $<TARGET_FILE:rt> compare ${soft_shadows} ${soft_shadows})
set_tests_properties(Cli.CompareUsesTheGradersThresholds PROPERTIES LABELS "cli"
  PASS_REGULAR_EXPRESSION "the grader's thresholds, from stages/10-sampling/grading.json: full points up to 1.50%")
add_test(NAME Cli.CompareOptionsReplaceTheGradersThresholds
  COMMAND $<TARGET_FILE:rt> compare ${soft_shadows} ${soft_shadows} --tolerance 2)
set_tests_properties(Cli.CompareOptionsReplaceTheGradersThresholds PROPERTIES LABELS "cli"
  FAIL_REGULAR_EXPRESSION "grader's thresholds")
# A page a lecturer publishes names its scene from stages/ on, never the folders above it (the
# lecturer's machine): exported from an absolute path, the page holds no absolute path.
add_test(NAME Cli.ExportWebShowsNoMachinePath
  COMMAND bash -c "\"$0\" export-web \"$1\" -o \"$2\" && grep -q 'stages/01-camera-rays/scenes/perspective_directions.json' \"$2\" && ! grep -q -- \"$3\" \"$2\""
          $<TARGET_FILE:rt> ${PROJECT_SOURCE_DIR}/stages/01-camera-rays/scenes/perspective_directions.json
          ${PROJECT_BINARY_DIR}/test-output/export-web-path.html ${PROJECT_SOURCE_DIR}/)
set_tests_properties(Cli.ExportWebShowsNoMachinePath PROPERTIES LABELS "cli;gpu")
# Damaged OBJ files (tests/bad_objs/expected.txt): one line naming the OBJ file and line, exit 1.
add_test(NAME Cli.DamagedObjFilesGiveOneLineErrors
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DDIR=${CMAKE_CURRENT_SOURCE_DIR}/tests/bad_objs
          -DOUT=${PROJECT_BINARY_DIR}/test-output/bad-objs
          -P ${PROJECT_SOURCE_DIR}/cmake/check_bad_objs.cmake)
set_tests_properties(Cli.DamagedObjFilesGiveOneLineErrors PROPERTIES LABELS "cli;scene")
# The ray-tree debugger's command line: JSON output, and a pixel outside the image.
add_test(NAME Cli.DebugPixelJson
  COMMAND $<TARGET_FILE:rt> render ${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json
          --debug-pixel 126,62 --debug-format json)
set_tests_properties(Cli.DebugPixelJson PROPERTIES LABELS "cli"
  PASS_REGULAR_EXPRESSION "\"tree\": {")
# --gpu: what the shader computed; the JSON form is the CPU tree's only.
add_test(NAME Cli.GpuDebugPixel
  COMMAND $<TARGET_FILE:rt> render ${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json
          --gpu --debug-pixel 100,80)
set_tests_properties(Cli.GpuDebugPixel PROPERTIES LABELS "cli;gpu"
  PASS_REGULAR_EXPRESSION "camera ray \\(depth 0\\) from .*pixel value \\(")
rt_cli_error_test(GpuDebugPixelJson "--debug-format json is the CPU ray tree's"
                  render ${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json --gpu
                  --debug-pixel 100,80 --debug-format json)
rt_cli_error_test(DebugPixelOutsideImage "--debug-pixel" render ${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json --debug-pixel 500,2)

# Every scene file of every stage is in canonical form (`rt fmt`, docs/scene-format.md#canonical-form).
file(GLOB rt_stage_scenes RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/stages/*/scenes/*.json)
add_test(NAME Scenes.CanonicalForm COMMAND $<TARGET_FILE:rt> fmt --check ${rt_stage_scenes}
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(Scenes.CanonicalForm PROPERTIES LABELS "scenes;docs")
# rt fmt itself: rewriting in place, --check naming the file, bad scenes in the loader's words.
set(rt_fmt_tests ${CMAKE_CURRENT_SOURCE_DIR}/tests/scene_format)
add_test(NAME Cli.FmtRewritesInPlaceOnce
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSCENE=${rt_fmt_tests}/not_canonical.json
          -DOUT=${PROJECT_BINARY_DIR}/test-output/fmt -P ${rt_fmt_tests}/check_fmt_rewrite.cmake)
set_tests_properties(Cli.FmtRewritesInPlaceOnce PROPERTIES LABELS "cli;scenes")
rt_cli_error_test(FmtCheckNamesTheFile "not_canonical.json: not in canonical form"
                  fmt --check ${rt_fmt_tests}/not_canonical.json)
rt_cli_error_test(FmtBadSceneGivesTheLoaderError "20-negative-radius.json:3:55: error:"
                  fmt ${bad}/20-negative-radius.json)
rt_cli_error_test(FmtInvalidJson "01-trailing-comma.json:4:3: error: invalid JSON"
                  fmt --check ${bad}/01-trailing-comma.json)
rt_cli_error_test(FmtMissingFile "no-such-scene.json:1:1: error: no such file" fmt no-such-scene.json)

# Only render/, apps/ and testing/ may include the stage API (framework/README.md).
add_test(NAME Framework.TrustBoundary
  COMMAND ${CMAKE_COMMAND} -DFRAMEWORK=${CMAKE_CURRENT_SOURCE_DIR}
          -P ${PROJECT_SOURCE_DIR}/cmake/check_trust_boundary.cmake)
set_tests_properties(Framework.TrustBoundary PROPERTIES LABELS "framework")
# No loop of includes between framework folders (docs/architecture.md#folders).
add_test(NAME Tree.FolderCycles COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/check_folder_cycles.sh
                                        ${CMAKE_CURRENT_SOURCE_DIR})
set_tests_properties(Tree.FolderCycles PROPERTIES LABELS "framework;docs")
# The size guide (docs/architecture.md#keeping-it-readable): warnings over 500 lines a file and
# 80 a function, a failure over twice that. The course's own code only: a student's tree is not
# held to it. SizeCeilingFails gives the script a 1001-line file, which must fail it.
if(RT_INSTRUCTOR)
  add_test(NAME Tree.SizeLimits COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/check_sizes.sh
                                             ${PROJECT_SOURCE_DIR})
  add_test(NAME Tree.SizeCeilingFails
    COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/check_size_ceiling.sh ${PROJECT_SOURCE_DIR})
  set_tests_properties(Tree.SizeLimits Tree.SizeCeilingFails PROPERTIES LABELS "framework;docs")
endif()

# The gallery page (rt gallery's index.html): every graded scene listed, every link resolves.
# This and the viewer sessions below compare renders made with the reference solution, so they
# are instructor-only (in a starter tree every scene fails and says nothing about the page).
if(RT_INSTRUCTOR)
add_test(NAME Gallery.IndexPage
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSOURCE=${PROJECT_SOURCE_DIR}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/gallery
          -P ${PROJECT_SOURCE_DIR}/cmake/check_gallery_page.cmake)
set_tests_properties(Gallery.IndexPage PROPERTIES LABELS "render;gallery" TIMEOUT 900)
endif()
# rt export-web's pages in headless Chromium (docs/viewer.md#lecture-demos-in-a-browser): each
# page's first frame against rt render. Without node, puppeteer-core or WebGL2 each says why: a
# skip in a starter tree, a failure in the instructor tree (rt_skip_pattern).
if(RT_INSTRUCTOR)
add_test(NAME Web.ExportMatchesCpu
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSOURCE=${PROJECT_SOURCE_DIR}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/web
          -P ${PROJECT_SOURCE_DIR}/cmake/check_web_export.cmake)
set_tests_properties(Web.ExportMatchesCpu PROPERTIES LABELS "web;render" TIMEOUT 300 COST 110)
rt_skip_pattern(Web.ExportMatchesCpu "SKIPPED: ")
# Stage 10's scenes, which the page accumulates over draws: slow on SwiftShader (160 s at their
# own 160x120), so at 80x60 (about 40 s) and a test of its own, started early.
add_test(NAME Web.SampledExportMatchesCpu
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSOURCE=${PROJECT_SOURCE_DIR}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/web-sampled -DSTAGES=1[01] -DSIZE=80x60
          -P ${PROJECT_SOURCE_DIR}/cmake/check_web_export.cmake)
set_tests_properties(Web.SampledExportMatchesCpu PROPERTIES LABELS "web;render" TIMEOUT 600
                     COST 50000)
rt_skip_pattern(Web.SampledExportMatchesCpu "SKIPPED: ")
# The page's switches (specular, shadows, ...) against rt render with the same switch.
add_test(NAME Web.TogglesMatchCpu
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSOURCE=${PROJECT_SOURCE_DIR}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/web-toggles
          -P ${PROJECT_SOURCE_DIR}/cmake/check_web_toggles.cmake)
set_tests_properties(Web.TogglesMatchCpu PROPERTIES LABELS "web;render" TIMEOUT 300 COST 40)
rt_skip_pattern(Web.TogglesMatchCpu "SKIPPED: ")
# A page whose student GLSL does not compile names the student's file and line.
add_test(NAME Web.CompileErrorNamesStudentLine
  COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSOURCE=${PROJECT_SOURCE_DIR}
          -DOUT=${PROJECT_BINARY_DIR}/test-output/web-compile-error
          -P ${PROJECT_SOURCE_DIR}/cmake/check_web_compile_error.cmake)
set_tests_properties(Web.CompileErrorNamesStudentLine PROPERTIES LABELS "web;render" TIMEOUT 120)
rt_skip_pattern(Web.CompileErrorNamesStudentLine "SKIPPED: ")
endif()
# The viewer under Xvfb (without xvfb-run, saying why: rt_skip_pattern): screenshots in
# build/test-output/view/.
if(TARGET rt_view AND RT_INSTRUCTOR)
  foreach(session "ScriptedSession;stages/05-recursion/scenes/whitted.json;session"
                  "TextureFilterAndBvh;stages/07-textures/scenes/textured_whitted.json;textures_session"
                  "NonFinitePixels;framework/tests/view/non_finite.json;non_finite_session")
    list(GET session 0 name)
    list(GET session 1 scene)
    list(GET session 2 script)
    add_test(NAME View.${name}
      COMMAND ${CMAKE_COMMAND} -DRT=$<TARGET_FILE:rt> -DSCENE=${PROJECT_SOURCE_DIR}/${scene}
              -DSCRIPT=${CMAKE_CURRENT_SOURCE_DIR}/tests/view/${script}.txt
              -DOUT=${PROJECT_BINARY_DIR}/test-output/view/${script}
              -P ${PROJECT_SOURCE_DIR}/cmake/check_view.cmake)
    set_tests_properties(View.${name} PROPERTIES LABELS "view;render" TIMEOUT 900 RESOURCE_LOCK xvfb)
    rt_skip_pattern(View.${name} "SKIPPED: xvfb-run is missing")
  endforeach()
endif()
if(TARGET rt_view)
  # Without a display: one line saying why and what to run instead.
  add_test(NAME Cli.ViewWithoutDisplay
    COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
            ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:rt>;view;${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json"
            "-DEXPECT=run under a desktop or `xvfb-run" -P ${PROJECT_SOURCE_DIR}/cmake/check_cli_error.cmake)
  set_tests_properties(Cli.ViewWithoutDisplay PROPERTIES LABELS "cli;view")
  # A bad script line is one error naming the file and line, before any window opens.
  rt_cli_error_test(ViewBadScript "bad_script.txt:3: error: unknown command \"frobnicate\""
                    view ${PROJECT_SOURCE_DIR}/stages/05-recursion/scenes/whitted.json
                    --script ${CMAKE_CURRENT_SOURCE_DIR}/tests/view/bad_script.txt)
endif()

# cmake/sanitizers/lsan.supp suppresses leaks allocated by calloc and realloc (llvmpipe's JIT
# code); it may, because the project's own code calls neither.
add_test(NAME Framework.NoCallocOrRealloc
  COMMAND bash -c "! grep -rnE '\\b(calloc|realloc)[[:space:]]*\\(' framework stages grader tools --include=*.cpp --include=*.h"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(Framework.NoCallocOrRealloc PROPERTIES LABELS "framework")

# Every student function has a judge proxy (stage_api/calls.h): the grading judge would otherwise
# fail to link, or, for a function no test calls yet, the next test that does.
add_test(NAME Framework.Remote.EveryStageFunctionHasAProxy
  COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/check_remote_proxies.sh $<TARGET_FILE:rt_stages>
          $<TARGET_FILE:rt_judge>)
set_tests_properties(Framework.Remote.EveryStageFunctionHasAProxy PROPERTIES LABELS "framework;remote")
# The leaderboard's traversal cost (apps/bvh_cost.h): a dumped tree costs what the tree costs, a
# poor one more, a broken one is refused in one line. The grader's (it needs stage 06 solved):
# instructor trees only.
if(RT_INSTRUCTOR)
  add_test(NAME Cli.BvhCostCountsAGivenTree
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tests/bvh_cost_cli.sh $<TARGET_FILE:rt>
            ${PROJECT_SOURCE_DIR}/stages/06-bvh/scenes/mesh_garden.json)
  set_tests_properties(Cli.BvhCostCountsAGivenTree PROPERTIES LABELS "cli;grader")
endif()
