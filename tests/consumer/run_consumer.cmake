# Installs the build into a scratch prefix, then configures, builds and runs
# the consumer project against it. -DSTRICT_HEADERS=ON: each header compiled
# with nothing precompiled (scripts/check_headers.sh).
if(NOT DEFINED STRICT_HEADERS)
  set(STRICT_HEADERS OFF)
endif()
if(NOT DEFINED LIBRARY_SOURCES)
  set(LIBRARY_SOURCES "")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                        -DSTRICT_HEADERS=${STRICT_HEADERS} -DLIBRARY_SOURCES=${LIBRARY_SOURCES}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configure of the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build --parallel 2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "build of the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer returned ${rc}")
endif()
# The installed command runs from its prefix, with no library path set
# (its RPATH is $ORIGIN/../lib), and finds its bundled data there.
file(GLOB installed_bin ${WORK_DIR}/prefix/bin/deepguide)
if(NOT installed_bin)
  message(FATAL_ERROR "no bin/deepguide in the installed prefix ${WORK_DIR}/prefix")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${installed_bin} --version
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "deepguide")
  message(FATAL_ERROR "the installed bin/deepguide did not run (${rc}): ${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${installed_bin} obstacles info
                        ${WORK_DIR}/prefix/share/deepguide/data/sample_obstacles.geojson
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "6 elliptical cylinder")
  message(FATAL_ERROR "the installed bin/deepguide could not read the installed sample (${rc}): ${out}${err}")
endif()
