# SPDX-License-Identifier: MIT
# mdrTargets.cmake as `make install` writes it (mk/install.mk): the target
# mdr::mdr, this prefix's static libmdr.a and its headers, for
# find_package(mdr) (cmake/mdrConfig.cmake). The CMake build's own install
# (`cmake --install`) writes its exported targets instead.
get_filename_component(_mdr_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET mdr::mdr)
  add_library(mdr::mdr STATIC IMPORTED)
  set_target_properties(mdr::mdr PROPERTIES
    IMPORTED_LOCATION "${_mdr_prefix}/lib/libmdr.a"
    INTERFACE_INCLUDE_DIRECTORIES "${_mdr_prefix}/include/mdr")
endif()
unset(_mdr_prefix)
