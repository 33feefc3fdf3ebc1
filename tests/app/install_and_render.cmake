# app.install: `cmake --install` of this build into a fresh prefix gives a usable desktop
# install — the executable, the menu entry (validated by desktop-file-validate) and its
# icon — and the installed trimlab renders the demo. Run by CTest under the suite's Xvfb:
#   cmake -DBUILD_DIR=<build> -DPREFIX=<empty folder> -DVALIDATOR=<desktop-file-validate>
#         -P install_and_render.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}${err}")
endif()
foreach(installed bin/trimlab share/applications/trimlab.desktop share/icons/hicolor/scalable/apps/trimlab.svg)
  if(NOT EXISTS "${PREFIX}/${installed}")
    message(FATAL_ERROR "cmake --install did not install ${installed}:\n${out}")
  endif()
endforeach()

if(NOT VALIDATOR)
  message(FATAL_ERROR "desktop-file-validate not found: install desktop-file-utils (scripts/install-deps)")
endif()
execute_process(COMMAND "${VALIDATOR}" "${PREFIX}/share/applications/trimlab.desktop"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
  message(FATAL_ERROR "trimlab.desktop is not a valid desktop entry (${rc}):\n${out}${err}")
endif()

set(image "${PREFIX}/pushed-sphere.png")
execute_process(COMMAND "${PREFIX}/bin/trimlab" render demo:pushed-sphere --rule alternating-border
                        --clip 0,0,-1,0 --size 96x72 -o "${image}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0 OR NOT EXISTS "${image}")
  message(FATAL_ERROR "the installed trimlab did not render (${rc}):\n${out}${err}")
endif()
file(READ "${image}" magic LIMIT 8 HEX)
if(NOT magic STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "${image} is not a PNG file (starts with ${magic})")
endif()
message(STATUS "installed into ${PREFIX}; the installed trimlab rendered ${image}")
