# CTest python_installed_package: `cmake --install` the build into PREFIX,
# then import railstab from there (PYTHONPATH=PREFIX/PACKAGE_DIR, nothing of
# the build tree on the path) and read a scene with it.
foreach(var BUILD_DIR PREFIX PACKAGE_DIR PYTHON SCENE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "python_install_test.cmake: -D${var}=... missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed (${rc}):\n${out}\n${err}")
endif()
set(check [=[
import os, sys, railstab
prefix = os.path.realpath(sys.argv[1])
assert os.path.realpath(railstab.__file__).startswith(prefix), railstab.__file__
s = railstab.load_scene(sys.argv[2])
print("installed railstab", railstab.__version__, "read", s.name)
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${PACKAGE_DIR}
                        ${PYTHON} -c "${check}" ${PREFIX} ${SCENE}
                WORKING_DIRECTORY ${PREFIX}  # not the build tree: python -c looks there first
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import from the installed package failed (${rc}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
file(REMOVE_RECURSE ${PREFIX})
