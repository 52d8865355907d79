// The syntax of one WL4 line (wl4.md §1, §6.8): the normative grammar of the dialect. The front
// end parses it twice over: dialects/wl4/block_parser.cpp is a recursive-descent parser written
// from these rules (the fast path), dialects/wl4/tree_builder.cpp builds the same IR from this
// grammar's tree. The block reader has already cut the line before the `$` comment and read sign
// aliases as '-'. Blanks may stand between tokens (§1.3) but not inside a number or a keyword, nor
// between N, L, '#' or IF<p> and their digits (the tree builder checks that adjacency).
grammar WL4;

// ---------------------------------------------------------------- lines

line
    : programStart EOF                       // `%name`: a program unit begins (§1.2)
    | programEnd EOF                         // `%` alone: it ends
    | SLASH? blockNumber? item* message? EOF // `/` block skip (§1.7), N first (§1.3)
    ;

// the name: letters, digits and '_', at most 80 characters (blanks are the reader's to refuse)
programStart : PERCENT (ADDRESS | N | L | WORD | DIGITS | UNDERSCORE | keyword)+ ;
programEnd   : PERCENT ;

blockNumber : N DIGITS ; // a leading 0 makes it a label: N010 is label 10 (§1.8)

item
    : N DIGITS                      // an N that is not first: jump to that label (§6.6)
    | L DIGITS                      // L nn / L nnpp: call %nn pp times (§6.7)
    | IF DIGITS? LPAREN expr RPAREN // IF<p> (cond): the rest of the block if cond holds (§6.5)
    | variable ASSIGN expr          // #n = expression, anywhere in the block (§6.4)
    | ADDRESS value                 // a word (§1.5)
    ;

// `.` where a word would start: text to the end of the line (§1.6), even `.5 MM STOCK`
message : (DOT | FRACTION) ~EOF* ;

// value = [sign] (number | varref ["=" factor] | "(" expr ")")
value
    : sign? number
    | sign? variable (ASSIGN factor)?
    | sign? LPAREN expr RPAREN
    ;

// ---------------------------------------------------------------- expressions (§6.3)
// Two levels, each left to right: ** * / MOD first, then + - relational AND OR XOR.

expr   : term (op2 term)* ;
term   : factor (op1 factor)* ;
factor : sign? primary ;
primary
    : number
    | variable (ASSIGN factor)?       // #n=factor assigns and yields the value (§6.4)
    | LPAREN expr RPAREN
    | ATAN LPAREN expr RPAREN SLASH LPAREN expr RPAREN // ATAN(a)/(b): the angle of (b, a)
    | ATAN LPAREN expr RPAREN                          // ATAN(a)/2 divides ATAN(a)
    | FUNCTION LPAREN expr RPAREN
    ;

variable : HASH DIGITS | HASH LPAREN expr RPAREN ; // #20, #(#20), #(ABS(#3-#4*2))

op1  : POW | STAR | SLASH | MOD ;
op2  : PLUS | MINUS | EQ | NE | LE | GE | LT | GT | AND | OR | XOR ;
sign : PLUS | MINUS ;
keyword : IF | MOD | AND | OR | XOR | ATAN | FUNCTION ;

number : DIGITS | DECIMAL | FRACTION ; // no point: whole millimetres, X1030 = 1030 mm

// ---------------------------------------------------------------- tokens
// A run of two or more letters is a keyword (or, not being one, an unknown word: WORD); one letter
// is an address (§6.8).

IF       : 'IF' ;
MOD      : 'MOD' ;
AND      : 'AND' ;
OR       : 'OR' ;
XOR      : 'XOR' ;
ATAN     : 'ATAN' ;
FUNCTION : 'ABS' | 'COS' | 'ACOS' | 'SIN' | 'ASIN' | 'TAN' | 'EXP' | 'FIX' | 'FUP' | 'LN'
         | 'ROUND' | 'SQRT' ;
N        : 'N' ;
L        : 'L' ;
ADDRESS  : [A-KM-Z] ; // every letter but L and N, which are calls and block numbers
WORD     : [A-Z] [A-Z]+ ;
DIGITS   : [0-9]+ ;
DECIMAL  : [0-9]+ '.' [0-9]* ;
FRACTION : '.' [0-9]+ ;
PERCENT  : '%' ;
UNDERSCORE : '_' ;
HASH     : '#' ;
LPAREN   : '(' ;
RPAREN   : ')' ;
EQ       : '==' ;
NE       : '<>' ;
LE       : '<=' ;
GE       : '>=' ;
LT       : '<' ;
GT       : '>' ;
ASSIGN   : '=' ;
POW      : '**' ;
STAR     : '*' ;
SLASH    : '/' ;
PLUS     : '+' ;
MINUS    : '-' ;
DOT      : '.' ;
BLANK    : ' ' -> skip ;
OTHER    : . ; // any other character: the parser refuses it where it stands, located
