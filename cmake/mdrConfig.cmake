# SPDX-License-Identifier: MIT
# mdrConfig.cmake: find_package(mdr) after `cmake --install` of libmdr;
# gives the target mdr::mdr.
include("${CMAKE_CURRENT_LIST_DIR}/mdrTargets.cmake")
