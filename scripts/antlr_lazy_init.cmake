# Run after antlr4 writes a grammar's C++ (CMakeLists.txt, "grammar"): the
# generated lexer and parser deserialize their ATN in a static initialiser,
# that is at the start of every robotsim process, for both grammars, needed
# or not. This moves each one into its class's constructor, as a
# function-local static (thread-safe, once), so only a process that lexes or
# parses pays for it (docs/performance.md, "Start-up").
# -DDIR=<generated folder> -DGRAMMAR=<RobotProgram|RobotModel>
foreach(kind Lexer Parser)
  set(class ${GRAMMAR}${kind})
  set(file ${DIR}/${class}.cpp)
  file(READ ${file} text)
  set(eager "${class}::Initializer ${class}::_init;")
  if(kind STREQUAL "Lexer")
    set(ctor "${class}::${class}(CharStream *input) : Lexer(input) {")
  else()
    set(ctor "${class}::${class}(TokenStream *input) : Parser(input) {")
  endif()
  string(FIND "${text}" "${eager}" at_eager)
  string(FIND "${text}" "${ctor}" at_ctor)
  if(at_eager EQUAL -1 OR at_ctor EQUAL -1)
    message(FATAL_ERROR "antlr_lazy_init.cmake: ${file} does not have the shape of ANTLR 4.9's output "
      "(\"${eager}\" and \"${ctor}\"); this ANTLR needs the script looked at")
  endif()
  string(REPLACE "${eager}" "// ${class}'s static initialiser: run by the constructor (scripts/antlr_lazy_init.cmake)."
    text "${text}")
  string(REPLACE "${ctor}" "${ctor}\n  static Initializer lazyInit;\n  (void)lazyInit;" text "${text}")
  file(WRITE ${file} "${text}")
endforeach()
