# The library's targets along its layers. A layer is a folder: public headers in
# include/sillage/<folder>/, sources and internal headers in src/sillage/<folder>/
# ("." is the top level of both). tests/python/test_public_headers.py reads the
# sillage_add_layers() calls of CMakeLists.txt for its include rule: keep each on one line.

# sillage_add_layers(<name> FOLDERS <folder>... [DEPENDS <name>...]): the static
# library sillage_<name> (sillage::<name> once installed) of those folders, linking
# only the targets it DEPENDS on.
function(sillage_add_layers name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FOLDERS;DEPENDS")
  set(files)
  foreach(folder IN LISTS arg_FOLDERS)
    file(GLOB found CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/sillage/${folder}/*.cpp
         ${PROJECT_SOURCE_DIR}/src/sillage/${folder}/*.h ${PROJECT_SOURCE_DIR}/include/sillage/${folder}/*.h)
    list(APPEND files ${found})
  endforeach()
  set(target sillage_${name})
  add_library(${target} STATIC ${files})
  add_library(sillage::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_compile_features(${target} PUBLIC cxx_std_20)
  # Public: the inline rounding code in the headers must not be contracted either.
  target_compile_options(${target} PRIVATE ${SILLAGE_CXX_FLAGS} PUBLIC -ffp-contract=off ${SILLAGE_ARCH_FLAGS})
  list(TRANSFORM arg_DEPENDS PREPEND sillage_)
  target_link_libraries(${target} PUBLIC ${arg_DEPENDS})
  # The layering, enforced: the whole target linked as a shared object with
  # only what it DEPENDS on and no undefined symbol allowed, so that a call
  # into a higher layer fails the build.
  if(SILLAGE_CHECK_LAYERS)
    add_library(${target}_closed SHARED ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
    target_link_libraries(${target}_closed PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,${target}>")
    target_link_options(${target}_closed PRIVATE -Wl,--no-undefined)
  endif()
endfunction()
