# The kit library's sources (nodes/ without the headless window and the bench), for the kit's own
# build and for the ParaView plugin's, which compiles them again against ParaView's VTK.
function(aokit_kit_sources out nodes_dir)
  file(GLOB_RECURSE all CONFIGURE_DEPENDS ${nodes_dir}/*.cpp)
  file(GLOB_RECURSE headless CONFIGURE_DEPENDS ${nodes_dir}/headless/*.cpp ${nodes_dir}/bench/*.cpp)
  list(REMOVE_ITEM all ${headless})
  set(${out} ${all} PARENT_SCOPE)
endfunction()
