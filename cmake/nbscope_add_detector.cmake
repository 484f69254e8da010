# nbscope_add_detector(NAME SOURCES...): a detector plugin that `nbscope --detector-lib NAME.so` loads.
# A MODULE library (never linked against, only dlopen'ed) named NAME.so without the "lib" prefix,
# compiled as C99 (C++ sources keep their own standard) with hidden visibility, so only what the
# plugin marks NBSCOPE_EXPORT (include/nbscope/detector.h) is exported.
function(nbscope_add_detector name)
  if(NOT ARGN)
    message(FATAL_ERROR "nbscope_add_detector(${name}): no source files")
  endif()
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE nbscope::detector_api)
  set_target_properties(${name} PROPERTIES
    PREFIX ""
    C_STANDARD 99
    C_STANDARD_REQUIRED ON
    C_EXTENSIONS OFF
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
endfunction()
