# Format.ClangFormat: fails, naming the files, when a C++ file of the project differs from
# what clang-format (with the repository's .clang-format) makes of it. Fix with
#   clang-format -i <files>
# Arguments: -DCLANG_FORMAT=<clang-format> -DSOURCE_DIR=<the repository>.
set(folders Filters Haptics ParaViewPlugin Testing)
set(files)
foreach(folder IN LISTS folders)
  file(GLOB_RECURSE found LIST_DIRECTORIES false
    "${SOURCE_DIR}/${folder}/*.cpp" "${SOURCE_DIR}/${folder}/*.cxx" "${SOURCE_DIR}/${folder}/*.h")
  list(APPEND files ${found})
endforeach()
list(FILTER files EXCLUDE REGEX "/Testing/Temporary/")
set(differ)
foreach(file IN LISTS files)
  execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror "${file}"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
  if(NOT status EQUAL 0)
    file(RELATIVE_PATH relative "${SOURCE_DIR}" "${file}")
    list(APPEND differ "${relative}")
  endif()
endforeach()
list(LENGTH files checked)
list(LENGTH differ count)
if(count GREATER 0)
  list(JOIN differ "\n  " listed)
  message(FATAL_ERROR "${count} of ${checked} C++ files differ from clang-format:\n  ${listed}")
endif()
message(STATUS "${checked} C++ files as clang-format wants them")
