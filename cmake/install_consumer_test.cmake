# CTest install_and_find_package: `cmake --install` the build into PREFIX,
# then configure and build the examples/ project against it with
# find_package(railstab), as a user of the library would, and run it on
# SCENE (optional). Fails on the first step that fails, with its output.
foreach(var BUILD_DIR PREFIX CONSUMER_BUILD CONSUMER_SOURCE CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_consumer_test.cmake: -D${var}=... missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${name}: ok")
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})
foreach(f include/railstab/setup/prepare_scene.hpp lib/cmake/railstab/railstabConfig.cmake
          lib/cmake/railstab/railstabConfigVersion.cmake lib/cmake/railstab/railstabTargets.cmake)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "install: ${PREFIX}/${f} missing")
  endif()
endforeach()
if(EXISTS ${PREFIX}/include/railstab/cli)
  message(FATAL_ERROR "install: the CLI headers (CLI11) must not be installed")
endif()
run_step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD}
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${PREFIX}
         -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
run_step("build consumer" ${CMAKE_COMMAND} --build ${CONSUMER_BUILD} -j1)
# The programs built against the installed package run: the thesis
# vehicle's critical speed (111.46 m/s) and its least damped lateral mode at
# 100 m/s (the numbers of the in-tree example tests, examples/CMakeLists.txt).
function(run_consumer program expected)
  execute_process(COMMAND ${CONSUMER_BUILD}/${program} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expected}")
    message(FATAL_ERROR "installed ${program}: exit ${rc}, expected '${expected}'\n${out}\n${err}")
  endif()
  message(STATUS "run consumer ${program}: ${out}")
endfunction()
if(DEFINED SCENE)
  run_consumer(critical_speed "critical speed 111\\.46 m/s" ${SCENE})
  run_consumer(eigen_at_speed "least damped lateral: -1\\.0753 1/s at 3\\.8964 Hz, bogie hunting"
               ${SCENE} 100)
endif()
