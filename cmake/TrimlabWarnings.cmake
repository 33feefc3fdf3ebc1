# Warnings for TrimLab's own targets. Third-party headers are included as SYSTEM
# (imported targets), so their warnings do not drown ours. With TRIMLAB_WERROR (set by
# scripts/build and .ci/run) every warning fails the build.
function(trimlab_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local
                                           -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual)
  if(TRIMLAB_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
    if(TRIMLAB_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      # Under -fsanitize, GCC 12 reports -Wmaybe-uninitialized inside OpenMesh's
      # Property.hh (std::vector::push_back of a default VectorT) where it inlines the
      # instrumented code; the plain build does not. It stays a printed warning there.
      target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized)
    endif()
  endif()
endfunction()
