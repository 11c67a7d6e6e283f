# report.html opens in headless Chromium (tests/report_render_test.py): it renders (the
# screenshot is not blank) and logs nothing on the console. Needs Debian's chromium and
# python3-pil (scripts/install_deps.sh); skipped (exit 77) only when no chromium is installed.
# Debian's /usr/bin/python3, not one that may come first on PATH (pyenv's has no PIL); change with
# -DCAMOPT_REPORT_PYTHON=/path/to/python3.
set(CAMOPT_REPORT_PYTHON /usr/bin/python3 CACHE FILEPATH "The Python that runs the report rendering test")
# In two shards of five examples (the ten in one test took 61 s on idle cores, 78 s beside a build).
foreach(shard RANGE 1)
  add_test(NAME Report.renders_in_chromium/shard${shard}
           COMMAND ${CAMOPT_REPORT_PYTHON} ${PROJECT_SOURCE_DIR}/tests/report_render_test.py
                   $<TARGET_FILE:camopt> ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/report-render-test-${shard}
                   --shard ${shard}/2)
  set_tests_properties(Report.renders_in_chromium/shard${shard} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
