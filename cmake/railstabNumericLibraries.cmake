# The numeric libraries railstab links, by library name: SUNDIALS 6.4
# (CVODES, i.e. CVODE with forward sensitivities, ARKODE, KINSOL, dense and KLU linear solvers), SuiteSparse KLU
# and ARPACK, as imported targets railstab::<lib>. By name because Debian's
# SUNDIALS CMake export also lists static targets whose files may be absent.
# Included by the build (CMakeLists.txt) and by the installed package
# (railstabConfig.cmake), so the list is written once, here.
#
# Sets RAILSTAB_NUMERIC_LIBS to the targets; when a library is missing,
# RAILSTAB_NUMERIC_MISSING to its name (the caller decides how to fail).
set(RAILSTAB_NUMERIC_LIBRARY_NAMES
    sundials_cvodes sundials_arkode sundials_kinsol sundials_nvecserial
    sundials_sunmatrixdense sundials_sunlinsoldense sundials_sunmatrixsparse
    sundials_sunlinsolklu klu amd colamd btf suitesparseconfig arpack)
set(RAILSTAB_NUMERIC_LIBS "")
unset(RAILSTAB_NUMERIC_MISSING)
foreach(_railstab_lib IN LISTS RAILSTAB_NUMERIC_LIBRARY_NAMES)
  if(NOT TARGET railstab::${_railstab_lib})
    find_library(railstab_${_railstab_lib}_LIBRARY NAMES ${_railstab_lib})
    if(NOT railstab_${_railstab_lib}_LIBRARY)
      set(RAILSTAB_NUMERIC_MISSING ${_railstab_lib})
      break()
    endif()
    add_library(railstab::${_railstab_lib} UNKNOWN IMPORTED)
    set_target_properties(railstab::${_railstab_lib} PROPERTIES
      IMPORTED_LOCATION ${railstab_${_railstab_lib}_LIBRARY})
  endif()
  list(APPEND RAILSTAB_NUMERIC_LIBS railstab::${_railstab_lib})
endforeach()
unset(_railstab_lib)
