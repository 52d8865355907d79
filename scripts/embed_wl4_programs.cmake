# Writes OUT, a C++ file holding the text of every DIR/*.wl4 (WL4's system programs %81-%89),
# so gcx carries them without files to install. Run by the build (CMakeLists.txt).
file(GLOB files ${DIR}/*.wl4)
list(SORT files)
set(body "")
foreach(f ${files})
  get_filename_component(name ${f} NAME_WE)
  file(READ ${f} text)
  string(APPEND body "      {\"${name}\", R\"WL4(${text})WL4\"},\n")
endforeach()
file(WRITE ${OUT} "// Generated from dialects/wl4/programs by scripts/embed_wl4_programs.cmake.
#include \"dialects/wl4/system_programs.h\"

namespace gcx::wl4 {

const std::vector<SystemProgramText>& systemProgramTexts() {
  static const std::vector<SystemProgramText> all = {
${body}  };
  return all;
}

} // namespace gcx::wl4
")
