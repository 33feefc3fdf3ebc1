# Warnings for TrimLab's own targets. Third-party headers are included as SYSTEM
# (imported targets), so their warnings do not drown ours.
function(trimlab_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local
                                           -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual)
  if(TRIMLAB_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
