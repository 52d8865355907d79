# Makes a generated ANTLR recognizer (FILE, class CLASS) build its ATN on first use, not at
# program start. ANTLR 4.7's C++ target deserializes every grammar's ATN in a static
# initializer: some 6.5 M instructions at each start of gcx, a tenth of a fast `gcx check` of
# a million lines, paid even by runs that never reach a grammar. Run by the build after
# ANTLR (CMakeLists.txt); it stops the build if the generated code has another shape.
file(READ ${FILE} text)

set(eager "${CLASS}::Initializer ${CLASS}::_init;")
set(construct "  _interpreter = new atn::")
foreach(needle "${eager}" "${construct}")
  string(FIND "${text}" "${needle}" first)
  string(FIND "${text}" "${needle}" last REVERSE)
  if(first EQUAL -1 OR NOT first EQUAL last)
    message(FATAL_ERROR "${FILE}: expected \"${needle}\" exactly once; ANTLR's output changed")
  endif()
endforeach()

# A function-local static: built once, on the first construction, safely across threads.
string(REPLACE "${eager}" "// ${CLASS}'s ATN is built by its first constructor call." text
       "${text}")
string(REPLACE "${construct}" "  static const Initializer buildOnce;\n${construct}" text "${text}")
file(WRITE ${FILE} "${text}")
