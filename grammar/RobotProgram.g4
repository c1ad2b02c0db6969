// The ROBOTSIM program language (.rsp), as ANTLR sees it.
//
// A program is lines. A line may carry a label ("loop:"), then a head word
// and its operands: an instruction ("MOVETO 100 0 0 0 0"), the POINTS
// header, or a taught point ("P1 100 0 0 0 0"). The grammar stays this flat
// on purpose: which head words exist and what operands each takes lives in
// the one opcode table (vm/opcodes.h) and is checked when the parse tree is
// turned into the AST, where a message can say exactly what was expected.
//
// The build generates the parser (and this lexer) with the antlr4 tool; the
// compiler feeds the parser from a hand-written lexer (compiler/program/lexer.cpp)
// that produces exactly these token types, several times faster.
grammar RobotProgram;

program : line (NEWLINE line)* EOF ;

// A line is a sequence of words. Which words may stand where (a label is
// a name followed by ':' at the start of a line, then a head word, then
// operands) is checked when the parse tree becomes the AST: there a
// message can name exactly what was expected, and an error never costs
// more than its own line. (A rule per word would add a tree node per
// word, token labels a dynamic_cast per word; both were measured.)
line    : (IDENT | NUMBER | CMP | COLON)* ;

IDENT   : [A-Za-z_] [A-Za-z0-9_]* ;
NUMBER  : [+-]? [0-9]+ ('.' [0-9]+)? ;
CMP     : '<' | '>' | '=' ;
COLON   : ':' ;
NEWLINE : '\r'? '\n' ;
COMMENT : ';' ~[\r\n]* -> skip ;
WS      : [ \t]+ -> skip ;
