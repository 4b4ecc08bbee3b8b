# The documentation's commands: every ```bash block of README.md and doc/*.md is run for real
# (against the nodes it needs) or checked (executables, flags, parameters, files, PlanPath
# fields); test/docs/doc_commands_test.py says how a block is marked.
if(CATKIN_ENABLE_TESTING)
  add_test(NAME doc_commands_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/docs/doc_commands_test.bash)
  set_tests_properties(doc_commands_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 600)
endif()
