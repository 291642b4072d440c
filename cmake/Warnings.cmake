# onelight_warnings(TARGET): the project's own code builds with zero warnings.
function(onelight_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wdouble-promotion -Werror)
endfunction()
