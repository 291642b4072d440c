# onelight_add_test(NAME SOURCES... [LABELS l...] [LIBS t...]): a GoogleTest executable whose
# cases appear in ctest one by one. Label `unit` marks the fast tests that CI also runs under
# the sanitizers (target onelight_unit_tests builds them all); `gpu` tests run on lavapipe with
# the validation layer on.
include(GoogleTest)
add_custom_target(onelight_unit_tests)

function(onelight_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LABELS;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES} ${T_UNPARSED_ARGUMENTS})
  onelight_warnings(${name})
  target_link_libraries(${name} PRIVATE GTest::gtest GTest::gtest_main ${T_LIBS})
  set(env "XDG_RUNTIME_DIR=${PROJECT_BINARY_DIR}/xdg")
  if("gpu" IN_LIST T_LABELS)
    list(APPEND env "ONELIGHT_VALIDATION=1")  # runtime/vk enables VK_LAYER_KHRONOS_validation
  endif()
  # ENVIRONMENT is a list: repeat the property name so that each entry survives discovery.
  string(REPLACE ";" ";ENVIRONMENT;" env "${env}")
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST
                       PROPERTIES LABELS "${T_LABELS}" ENVIRONMENT "${env}")
  if("unit" IN_LIST T_LABELS)
    add_dependencies(onelight_unit_tests ${name})
  endif()
endfunction()
