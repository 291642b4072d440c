# onelight_add_tests(NAME
#     [UNIT sources...] [NUMERICS sources...] [LAB sources...] [CLI sources...] [GPU sources...]
#     [SOURCES sources without tests...] [LIBS targets...])
#
# One GoogleTest executable (one per tests/ folder), whose cases appear in ctest one by one,
# each labelled by the group its source file is listed under:
#   unit      fast tests of one piece; CI also runs them under ASan and UBSan
#   numerics  numerical tests against independent references (integrals, closed forms, the
#             path tracer): the same code as unit, with long loops; run once, not under ASan
#   lab       the lab's command line
#   cli       the command-line programs run as a user runs them (bad input, interrupts); under
#             ASan and UBSan too
#   gpu       on lavapipe with the validation layer on (ONELIGHT_VALIDATION=1)
#   slurm     bakes on a single-node Slurm that the test starts on localhost: one at a time
#             (fixed ports), skipped where Slurm is not installed
# A source's label reaches its cases through a gtest filter built from the suites it declares
# (TEST, TEST_F, TEST_P), read here at configure time; a suite declared under two labels is an
# error. Editing a test source reconfigures, so that a new suite is registered.
# Target onelight_sanitized_tests builds every executable with unit or cli tests (the ones
# scripts/sanitize.sh runs under ASan and UBSan).
include(GoogleTest)
add_custom_target(onelight_sanitized_tests)
set(onelight_test_labels UNIT NUMERICS LAB CLI GPU SLURM)

# The suites a test source declares, as a gtest filter ("A.*:*/A.*:B.*:*/B.*").
function(onelight_suite_filter source out_filter out_suites)
  get_filename_component(path ${source} ABSOLUTE)
  file(STRINGS ${path} lines REGEX "^[ \t]*(TEST|TEST_F|TEST_P|TYPED_TEST)\\(")
  set(suites)
  foreach(line ${lines})
    string(REGEX REPLACE "^[ \t]*[A-Z_]+\\([ \t]*([A-Za-z0-9_]+).*" "\\1" suite "${line}")
    list(APPEND suites ${suite})
  endforeach()
  list(REMOVE_DUPLICATES suites)
  set(filter)
  foreach(suite ${suites})
    list(APPEND filter "${suite}.*" "*/${suite}.*")
  endforeach()
  string(REPLACE ";" ":" filter "${filter}")
  set(${out_filter} "${filter}" PARENT_SCOPE)
  set(${out_suites} "${suites}" PARENT_SCOPE)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
endfunction()

function(onelight_add_tests name)
  cmake_parse_arguments(T "" "" "${onelight_test_labels};SOURCES;LIBS" ${ARGN})
  if(T_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "onelight_add_tests(${name}): unexpected ${T_UNPARSED_ARGUMENTS}")
  endif()
  set(all_sources ${T_SOURCES})
  foreach(label ${onelight_test_labels})
    list(APPEND all_sources ${T_${label}})
  endforeach()
  add_executable(${name} ${all_sources})
  onelight_warnings(${name})
  target_link_libraries(${name} PRIVATE GTest::gtest GTest::gtest_main ${T_LIBS})
  if(T_UNIT OR T_CLI)
    add_dependencies(onelight_sanitized_tests ${name})
  endif()

  set(seen)  # suites of the labels before this one
  foreach(label ${onelight_test_labels})
    if(NOT T_${label})
      continue()
    endif()
    string(TOLOWER ${label} lower)
    set(filter)
    set(these)
    foreach(source ${T_${label}})
      onelight_suite_filter(${source} source_filter suites)
      if(NOT suites)
        message(FATAL_ERROR "onelight_add_tests(${name}): ${source} declares no test; list it "
                            "under SOURCES")
      endif()
      foreach(suite ${suites})
        if(suite IN_LIST seen)
          message(FATAL_ERROR "onelight_add_tests(${name}): suite ${suite} of ${source} is "
                              "declared under two labels; each suite belongs to one")
        endif()
      endforeach()
      list(APPEND these ${suites})
      list(APPEND filter ${source_filter})
    endforeach()
    list(APPEND seen ${these})
    string(REPLACE ";" ":" filter "${filter}")
    # The caches (Mesa's shader cache, the game's pipeline cache) in the build, not the user's home.
    set(env "XDG_RUNTIME_DIR=${PROJECT_BINARY_DIR}/xdg" "XDG_CACHE_HOME=${PROJECT_BINARY_DIR}/cache")
    if(lower STREQUAL "gpu")
      list(APPEND env "ONELIGHT_VALIDATION=1")  # runtime/vk enables VK_LAYER_KHRONOS_validation
    endif()
    # ENVIRONMENT is a list: repeat the property name so that each entry survives discovery.
    string(REPLACE ";" ";ENVIRONMENT;" env "${env}")
    set(extra)
    if(lower STREQUAL "slurm")
      set(extra RESOURCE_LOCK local_slurm TIMEOUT 300 SKIP_REGULAR_EXPRESSION "\\[  SKIPPED \\]")
    endif()
    gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST TEST_FILTER "${filter}"
                         PROPERTIES LABELS ${lower} ENVIRONMENT "${env}" ${extra})
  endforeach()
endfunction()
