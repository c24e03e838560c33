# The prefix line of sillage.pc. The file is relocatable: its prefix is found
# from its own folder, which lies one level deeper on multiarch systems
# (lib/x86_64-linux-gnu/pkgconfig), so the way up is computed from the libdir.
function(sillage_pc_prefix out libdir install_prefix)
  if(IS_ABSOLUTE "${libdir}")
    set(${out} "${install_prefix}" PARENT_SCOPE)
  else()
    file(RELATIVE_PATH up "/p/${libdir}/pkgconfig" "/p")
    string(REGEX REPLACE "/$" "" up "${up}")  # CMake may end it with a slash
    set(${out} "\${pcfiledir}/${up}" PARENT_SCOPE)
  endif()
endfunction()
