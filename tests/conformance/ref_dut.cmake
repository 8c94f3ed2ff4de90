# The conformance kit on a DUT unlike zb_rop: conformance/ref's zb_ref_rop, run by
# scripts/conformance.py with its profile (conformance/ref/profile.json). Included by
# CMakeLists.txt; not in the sanitizer tree, as the other simulator tests.
#
# The expected counts, worked out from what each test draws (the PASS words of its stream.hex,
# decoded by a throwaway script, and the methods' pass plans in docs/datapath.md), not from
# conformance.py. The profile: blend replace and alpha, every depth function, depth write, colour
# mask, every width. Of the 12 methods each scene is exported with, opaque, unsorted, three-pass,
# back-front (replace and alpha, less), hidden-line (colour mask 0, lequal) and hidden-line-dim
# (greater) are supported; facing-additive (additive), coverage-aa (coverage), depth-peel-2/4/8
# (under, the peel test) and wboit (accumulate) are not, nor the hazard and random streams (every
# blend mode); random-core (and -d16, -d32), the random stream kept to replace and alpha without
# the peel test, is. So d24-c16: 10 scenes x 6 methods + random-core = 61 of 124; d24-c4
# (hazard-c4, random-c4): 0 of 2; d16-c16 and d32-c16: 3 scenes x {three-pass, hidden-line} +
# random-core = 7 of 13 each. Suite version 6's generated tests add, for this profile, the
# replace and alpha blends' states (states-replace, states-alpha; the -peel ones need the peel
# test), depth-bits at the three widths, values-replace and values-alpha, tiles and
# same-pixel-alpha (its second pass replaces under lequal): 9 of the 28 generated. Version 7's 24
# layers tests (blend 6) add none. Version 8 adds at 16 and at 32 bits cad-opaque, the states and
# values of replace, alpha and additive, the same-pixel runs of alpha and additive, and tiles: 7 of
# those 10 each (not the additive ones). The suite: 98 supported, 126 NOT SUPPORTED; its cad-*
# tests: 6 + 3 + 3 = 12 of 24, and random-core.
if(NOT ZBLEND_SANITIZE)
  set(ref ${CMAKE_CURRENT_SOURCE_DIR}/test_ref_dut.sh)
  set(zb $<TARGET_FILE:zblend>)
  set(w ${CMAKE_CURRENT_BINARY_DIR})
  # Lint: both variants (zb_ref_rop with and without ZB_REF_FULL, zb_ref_pipe), with no defect,
  # with every defect of conformance/ref/defects.json at once and with each alone (about 13 s).
  add_test(NAME conformance_ref_lint COMMAND ${ref} lint)
  # The whole suite: Verilator builds three configurations (3 to 5 s each) and runs the 98 tests
  # in a few seconds.
  add_test(NAME conformance_ref_verilator
           COMMAND ${ref} pass verilator ${suite} ${w}/ref-verilator ${zb} "" 98 126)
  # Icarus: every cad test, at the three depth widths the supported tests come in, and the
  # random stream of every depth function.
  add_test(NAME conformance_ref_icarus
           COMMAND ${ref} pass icarus ${suite} ${w}/ref-icarus ${zb} "cad-*,random-core" 13 12)
  # Another stall seed, most cycles stalled (160 of 256) and gaps in the fragment stream.
  add_test(NAME conformance_ref_random_stalls
           COMMAND ${ref} stalls verilator ${suite} ${w}/ref-stalls ${zb} "" 98 126 7 160 25
                   cad-three-pass)
  add_test(NAME conformance_ref_bug
           COMMAND ${ref} bug verilator ${suite} ${w}/ref-bug ${zb} cad-opaque,cad-three-pass
                   cad-three-pass)
  add_test(NAME conformance_ref_hang
           COMMAND ${ref} hang icarus ${suite} ${w}/ref-hang ${zb} cad-opaque)
  # The full datapath (ZB_REF_FULL) and the pipelined variant, clean: the quick tier on Icarus
  # (every test: 33), the whole suite on Verilator for the pipeline (its 117 of 224: replace,
  # alpha, additive, every depth function, depth write, colour mask).
  set(refdir ${PROJECT_SOURCE_DIR}/conformance/ref)
  add_test(NAME conformance_ref_full
           COMMAND ${ref} pass icarus ${suite} ${w}/ref-full ${zb} "" 33 0 --quick
                   --profile ${refdir}/profile_full.json)
  add_test(NAME conformance_ref_pipe
           COMMAND ${ref} pass verilator ${suite} ${w}/ref-pipe ${zb} "" 117 107
                   --profile ${refdir}/profile_pipe.json)
  # Upgrading the kit never breaks an adapter (docs/conformance.md "Adapter versions"): the
  # second DUT's adapter as it was at interface version 6 (tests/conformance/adapter_v6, before
  # the layers port) builds and passes what it passed on both simulators; today's adapter, of
  # version 7, is conformance_ref_verilator's. Then the versions read off the ports, without a run.
  set(v6 ${CMAKE_CURRENT_SOURCE_DIR}/adapter_v6/profile.json)
  add_test(NAME conformance_adapter_v6_verilator
           COMMAND ${ref} pass verilator ${suite} ${w}/adapter-v6-verilator ${zb} "" 98 126
                   --profile ${v6})
  add_test(NAME conformance_adapter_v6_icarus
           COMMAND ${ref} pass icarus ${suite} ${w}/adapter-v6-icarus ${zb} "cad-*,random-core" 13 12
                   --profile ${v6})
  add_test(NAME conformance_adapter_versions
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_adapter_versions.sh ${suite} ${w}/adapter-versions)
  add_test(NAME conformance_checkout
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_checkout.sh ${suite} ${w}/checkout)
  set_tests_properties(conformance_adapter_v6_verilator conformance_adapter_v6_icarus
                       conformance_adapter_versions conformance_checkout
                       PROPERTIES LABELS conformance FIXTURES_REQUIRED conformance_suite)
  # Declared arithmetic: the DUT built in each of three rules other than zblend's (round(sum /
  # 255), ceil(sum / 256), floor(sum / 256)) and declaring it passes; the ceil rule declared as
  # zblend's fails exactly the tests whose planes the two rules make differently.
  set(arith ${CMAKE_CURRENT_SOURCE_DIR}/test_ref_arith.sh)
  add_test(NAME conformance_arith_round255
           COMMAND ${arith} pass verilator ${suite} ${w}/arith-round255 ${zb}
                   ZB_REF_ARITH_SUM_ROUND255 sum-round255)
  add_test(NAME conformance_arith_ceil256
           COMMAND ${arith} pass icarus ${suite} ${w}/arith-ceil256 ${zb}
                   ZB_REF_ARITH_SUM_CEIL256 sum-ceil256 --quick)
  add_test(NAME conformance_arith_floor256
           COMMAND ${arith} pass icarus ${suite} ${w}/arith-floor256 ${zb}
                   ZB_REF_ARITH_SUM_FLOOR256 sum-floor256 --quick)
  add_test(NAME conformance_arith_wrong
           COMMAND ${arith} wrong verilator ${suite} ${w}/arith-wrong ${zb}
                   ZB_REF_ARITH_SUM_CEIL256 sum-ceil256)
  # A DUT that cannot say how it rounds asks for the CTS verdict: the ceil rule passes by the
  # threshold (counted apart), an alpha blend that skips blending for alpha >= 128 fails.
  add_test(NAME conformance_arith_cts
           COMMAND ${arith} cts icarus ${suite} ${w}/arith-cts ${zb} ZB_REF_ARITH_SUM_CEIL256 - --quick)
  add_test(NAME conformance_arith_cts_fails
           COMMAND ${arith} cts-fails icarus ${suite} ${w}/arith-cts-fails ${zb}
                   ZB_REF_ARITH_SUM_CEIL256,ZB_REF_DEFECT_ALPHA_OPAQUE_MSB - --quick)
  set_tests_properties(conformance_arith_round255 conformance_arith_ceil256
                       conformance_arith_floor256 conformance_arith_wrong conformance_arith_cts
                       conformance_arith_cts_fails
                       PROPERTIES LABELS conformance FIXTURES_REQUIRED conformance_suite)
  # The defect catalogue (conformance/ref/defects.json): each defect against the quick tier on
  # Icarus, stopping at the first failing test, which the line names; the quick tier, chosen by the
  # reach alone, catches all of them. make conformance runs each against the whole suite.
  file(READ ${refdir}/defects.json catalogue)
  string(JSON ndefects LENGTH ${catalogue})
  math(EXPR last "${ndefects} - 1")
  set(defect_tests)
  foreach(i RANGE ${last})
    string(JSON name GET ${catalogue} ${i} name)
    add_test(NAME conformance_defect_${name}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_ref_defects.sh ${suite} ${w}/defects ${zb}
                     --sim icarus --quick --first-fail -j 1 -- ${name})
    list(APPEND defect_tests conformance_defect_${name})
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${refdir}/defects.json)
  # The seeded random tier exported and run on the subset, with random timing from the seed.
  add_test(NAME conformance_seeded_tier
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_seeded_tier.sh ${zb} 11)
  set_tests_properties(conformance_seeded_tier PROPERTIES LABELS conformance)
  # conformance check after a --quick run of the subset: the tests the run simulated, from
  # OUT/results.json; check --quick. The progress lines of a run the checker fails never say ok.
  add_test(NAME conformance_check_run
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_check_run.sh ${suite} ${w}/check-run ${zb})
  add_test(NAME conformance_progress
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test_progress.sh ${suite} ${w}/progress ${zb})
  set_tests_properties(conformance_ref_verilator conformance_ref_icarus
                       conformance_ref_random_stalls conformance_ref_bug conformance_ref_hang
                       conformance_ref_full conformance_ref_pipe ${defect_tests}
                       conformance_check_run conformance_progress
                       PROPERTIES LABELS conformance FIXTURES_REQUIRED conformance_suite)
  set_tests_properties(conformance_ref_lint PROPERTIES LABELS conformance)
  set_tests_properties(conformance_ref_hang PROPERTIES TIMEOUT 120)
endif()
