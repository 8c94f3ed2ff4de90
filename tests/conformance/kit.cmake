# The kit as an outside team installs it (docs/conformance.md "The kit"): libzbgolden.so through
# the Python module, and zblend-conformance, the exporter and checker without the RTL. Included by
# CMakeLists.txt beside it. Not in the sanitizer trees: neither target is built there (a
# program loading the library would need the sanitizers' runtimes).
if(NOT ZBLEND_SANITIZE)
  # A Python 3 with NumPy: the one on PATH, else Debian's (scripts/setup.sh installs NumPy for
  # it); without one the tests fail on the module's line naming the package.
  set(kit_python "")
  find_program(kit_path_python python3)
  foreach(candidate IN ITEMS ${kit_path_python} /usr/bin/python3)
    if(NOT kit_python AND EXISTS ${candidate})
      execute_process(COMMAND ${candidate} -c "import numpy" RESULT_VARIABLE no_numpy
                      OUTPUT_QUIET ERROR_QUIET)
      if(no_numpy EQUAL 0)
        set(kit_python ${candidate})
      endif()
    endif()
  endforeach()
  if(NOT kit_python)
    set(kit_python /usr/bin/python3)
  endif()
  set(kit_py ${PROJECT_SOURCE_DIR}/conformance/python)
  set(kit_lib $<TARGET_FILE:zbgolden>)

  # Tests of each kind through the module and the shared library, every plane against the
  # expect files: scenes, the accumulation plane and its resolve, the hazard and random
  # streams, other depth and sample widths.
  add_test(NAME conformance_python
           COMMAND ${kit_python} ${kit_py}/zbgolden.py --lib ${kit_lib} ${suite}
                   cad-three-pass glass-torus-wboit hazard random-wboit cad-three-pass-d16
                   hazard-c4)
  # The issue's acceptance: `python3 -c` loads the library through the module, reads a plane.
  add_test(NAME conformance_python_oneliner
           COMMAND ${kit_python} -c "import zbgolden; p = zbgolden.Suite('${suite}').replay('cad-three-pass').plane('color'); print('plane', p.shape, p.dtype, hex(p[12, 16]))")
  set_tests_properties(conformance_python_oneliner PROPERTIES
                       ENVIRONMENT "PYTHONPATH=${kit_py};ZBGOLDEN_LIB=${kit_lib}"
                       PASS_REGULAR_EXPRESSION "plane \\(24, 32\\) uint32 0x[0-9a-f]+")
  # Failures are ZbGoldenError with the C API's line; a changed expect word is found.
  add_test(NAME conformance_python_errors
           COMMAND ${kit_python} ${kit_py}/test_kit.py errors ${kit_lib} ${suite} glass-torus-wboit)
  # zblend-conformance: its export equals zblend's, its check passes the expect files.
  add_test(NAME conformance_kit_program
           COMMAND ${kit_python} ${kit_py}/test_kit.py program $<TARGET_FILE:zblend-conformance>
                   $<TARGET_FILE:zblend> ${CMAKE_CURRENT_BINARY_DIR}/kit-program)
  # A corrupt suite (a fragment's alpha changed, an expect file gone): conformance.py, pixel and
  # check of both programs refuse it, exit 2, in the same words.
  add_test(NAME conformance_corrupt_suite
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_corrupt_suite.sh $<TARGET_FILE:zblend>
                   $<TARGET_FILE:zblend-conformance>)
  set_tests_properties(conformance_python conformance_python_oneliner conformance_python_errors
                       PROPERTIES FIXTURES_REQUIRED conformance_suite)
  set_tests_properties(conformance_python conformance_python_oneliner conformance_python_errors
                       conformance_kit_program conformance_corrupt_suite
                       PROPERTIES LABELS conformance)
endif()
