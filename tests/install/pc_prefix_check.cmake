# cmake -P check of sillage_pc_prefix: the way up from the .pc folder to the
# prefix for the usual and the multiarch library folders.
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/pc_prefix.cmake)
foreach(case "lib|\${pcfiledir}/../.." "lib64|\${pcfiledir}/../.."
             "lib/x86_64-linux-gnu|\${pcfiledir}/../../..")
  string(REPLACE "|" ";" pair "${case}")
  list(GET pair 0 libdir)
  list(GET pair 1 expected)
  sillage_pc_prefix(got "${libdir}" "/usr")
  if(NOT got STREQUAL expected)
    message(FATAL_ERROR "libdir ${libdir}: prefix ${got}, expected ${expected}")
  endif()
endforeach()
sillage_pc_prefix(got "/opt/x/lib" "/opt/x")
if(NOT got STREQUAL "/opt/x")
  message(FATAL_ERROR "absolute libdir: prefix ${got}, expected /opt/x")
endif()
message(STATUS "sillage.pc prefixes ok")
