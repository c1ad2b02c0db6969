// Robot and workcell descriptions (.rsd): the paper's DESIGN module as text.
//
// A description is lines. Blocks open with a kind and a name
// ("LINK upper_arm", "ROBOT scorobot") and close with "END"; inside, each
// line is a statement: a keyword and its arguments ("BOX -20 797 25 -25 20
// -20 COLOR RED", "JOINT 1 REVOLUTE LETTER E ..."). As for programs, the
// grammar stays flat: which statements a block takes and what their
// arguments are is checked when the parse tree becomes the model
// (compiler/description/description.cpp), where a message can say exactly what was
// expected. Unlike programs, descriptions are lexed by the lexer ANTLR
// generates from this file, a line at a time (the `description` and `line`
// rules say what is read; the reader takes a line's words straight from
// the lexer, as they take any words, so that memory stays a small multiple
// of the file: description.cpp).
grammar RobotModel;

description : line (NEWLINE line)* EOF ;

line        : (NAME | NUMBER | OTHER)* ;

// Names may hold '-' and '.' after the first character: "rhino-scara".
NAME        : [A-Za-z_] [A-Za-z0-9_.\-]* ;
NUMBER      : [+-]? ([0-9]+ ('.' [0-9]*)? | '.' [0-9]+) ;
NEWLINE     : '\r'? '\n' ;
COMMENT     : ';' ~[\r\n]* -> skip ;
WS          : [ \t\r]+ -> skip ;
// Anything else is one token the model builder reports with its position.
OTHER       : . ;
