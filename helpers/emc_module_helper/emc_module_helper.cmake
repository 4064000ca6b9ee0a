# emc_module_helper_executable(TARGET MODULE_DIR [FAKE_CALLS_FILE]): the helper with
# its whitelist (modules.manifest + rtapi + hal_lib + rtapi_parport_linux) and module directory compiled in.
# Used by this directory's CMakeLists.txt (the installed helper) and by the unit tests
# (a copy that logs its system calls to FAKE_CALLS_FILE instead of making them).
function(emc_module_helper_executable target module_dir)
  file(STRINGS ${CMAKE_SOURCE_DIR}/modules.manifest lines REGEX "^[a-z]")
  set(names "\"rtapi\", \"hal_lib\", \"rtapi_parport_linux\"")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "^[a-z0-9_]+" name "${line}")
    string(APPEND names ", \"${name}\"")
  endforeach()
  set(gen ${CMAKE_CURRENT_BINARY_DIR}/${target}_gen)
  file(CONFIGURE OUTPUT ${gen}/emc_module_whitelist.h
       CONTENT "/* generated from modules.manifest */\n#define EMC_MODULE_WHITELIST ${names}\n")
  add_executable(${target} ${CMAKE_SOURCE_DIR}/helpers/emc_module_helper/emc_module_helper.c)
  target_include_directories(${target} PRIVATE ${gen})
  target_compile_definitions(${target} PRIVATE EMC_MODULE_DIR="${module_dir}"
                             EMC_MODULE_SUBDIR="${HAL_KMOD_INSTALL_SUBDIR}")
  if(ARGC GREATER 2)
    target_compile_definitions(${target} PRIVATE EMC_FAKE_CALLS="${ARGV2}")
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()
