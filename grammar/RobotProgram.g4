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
// compiler feeds the parser from a hand-written lexer (compiler/lexer.cpp)
// that produces exactly these token types, several times faster.
grammar RobotProgram;

program : line (NEWLINE line)* EOF ;

// A line's words are plain tokens, with no rule or label per operand: the
// AST builder walks them in order. The first word is a label when a colon
// follows it ("loop: ADD N 1"), else the head word. (Token labels such as
// `head=IDENT` would make the generated code dynamic_cast on every word;
// an operand rule would add a tree node per word. Both were measured.)
// Written this way the rule is LL(1): no adaptive prediction per line.
line    : (IDENT (COLON IDENT?)? (NUMBER | IDENT | CMP)*)? ;

IDENT   : [A-Za-z_] [A-Za-z0-9_]* ;
NUMBER  : [+-]? [0-9]+ ('.' [0-9]+)? ;
CMP     : '<' | '>' | '=' ;
COLON   : ':' ;
NEWLINE : '\r'? '\n' ;
COMMENT : ';' ~[\r\n]* -> skip ;
WS      : [ \t]+ -> skip ;
