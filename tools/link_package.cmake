# Fills TARGET with a symlink to every entry of the package folder SOURCE except
# what an in-place build makes (the .so files, the BLAS probe, the plugin kit's
# include/ and cmake/) and __pycache__: the build in TARGET provides those.
# Used by the sanitizer build (CMakeLists.txt, BEAMSOLID_PACKAGE_DIR).
file(MAKE_DIRECTORY "${TARGET}")
file(GLOB _entries RELATIVE "${SOURCE}" "${SOURCE}/*")
foreach(_name IN LISTS _entries)
  if(_name MATCHES "\\.so$" OR _name MATCHES "^(__pycache__|beamsolid_blas|include|cmake)$")
    continue()
  endif()
  if(NOT IS_SYMLINK "${TARGET}/${_name}")
    file(CREATE_LINK "${SOURCE}/${_name}" "${TARGET}/${_name}" SYMBOLIC)
  endif()
endforeach()
# Drop links whose source entry is gone (a renamed or deleted module).
file(GLOB _links RELATIVE "${TARGET}" "${TARGET}/*")
foreach(_name IN LISTS _links)
  if(IS_SYMLINK "${TARGET}/${_name}" AND NOT EXISTS "${SOURCE}/${_name}")
    file(REMOVE "${TARGET}/${_name}")
  endif()
endforeach()
