# The kind of each GoogleTest test, a CTest label beside its module's: unit, property, e2e,
# platform or stress (golden is the replays' own label, set where they are added). CTest includes
# this file after discovery (cardemo_test_module); tests/support/check_test_kinds.py checks that
# every test has exactly one kind and that the suites below are the ones that run the binary.
#
#   platform  the real window under Xvfb: the only kind `scripts/test.sh` gives a second try
#   e2e       runs the cardemo executable and reads its output or files
#   stress    the stress module (long drives, scaled by CARDEMO_STRESS_SCALE)
#   property  seeded random cases against an oracle or a brute-force twin
#   unit      everything else: named cases of one piece
set(cardemo_platform_suites PlayE2e LevelE2e)
set(cardemo_e2e_suites Cli CompareCli CompareWorldCli RenderCommand ReferencedPaths PlayNoDisplay
    RecordingKill)
set(cardemo_property_pattern "Random|BruteForce|Twin|Invariance|Mutation|LongRun|Seeded|RoundTrip")

# cardemo_test_kind(OUT TEST MODULE): the kind of the discovered test TEST ("Suite.Name", or
# "Prefix/Suite.Name/Param") of MODULE.
function(cardemo_test_kind out test module)
  string(REGEX REPLACE "^([^/]*/)?([^./]+)\\..*" "\\2" suite "${test}")
  # list(FIND), not IN_LIST: CTest reads this file with no policies set.
  list(FIND cardemo_platform_suites "${suite}" platform_at)
  list(FIND cardemo_e2e_suites "${suite}" e2e_at)
  if(module STREQUAL "stress")
    set(kind stress)
  elseif(platform_at GREATER -1)
    set(kind platform)
  elseif(e2e_at GREATER -1)
    set(kind e2e)
  elseif(test MATCHES "${cardemo_property_pattern}")
    set(kind property)
  else()
    set(kind unit)
  endif()
  set(${out} ${kind} PARENT_SCOPE)
endfunction()
