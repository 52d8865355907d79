// NCT milling-channel block grammar (nct.md §1, nct-macro.md §1-§5).
//
// One parse = one block. The block reader (src/front/block_reader) has already
//  * split the file into blocks (LF outside comments ends a block, nct.md §1.5),
//  * folded letters to upper case outside comments (nct.md §1.1, macro L2),
//  * mapped the sign aliases `!`, U+2013, U+2212 to `-` (nct.md §0.1),
// so this grammar sees ASCII upper-case text. Whitespace is insignificant (nct.md §1.2 rule 8).
grammar NCT;

// ---------------------------------------------------------------- blocks
block
    : programStart EOF
    | blockSkip? sequenceNumber? body EOF
    ;

programStart : PERCENT (O NUMBER)? ;      // `%` or `%O0001` heading line (nct.md §1.8)
blockSkip    : SLASH NUMBER? ;             // `/` = `/1`; `/n` (nct.md §1.6)
sequenceNumber : N PLUS? NUMBER ;          // the first N of a block (§1.7); `+` is discarded (§1.2 rule 3)

body
    : statement
    | word*
    ;

// ---------------------------------------------------------------- NC words
word
    : address I? value                              # addressWord    // I = incremental operator
    | COMMA address value                           # commaWord      // ,C ,R ,A
    | AX LBRACK expr RBRACK ASSIGN I? value         # axisNumberWord // AX[e]=v
    | PATH                                          # pathWord       // M98 <file>, G65 <file>
    ;

address
    : A | B | C | D | E | F | G | H | I | J | K | L | M
    | N | O | P | Q | R | S | T | U | V | W | X | Y | Z
    ;

// `I` directly after an address is the incremental operator, never the I address: an address
// always needs a value, so `XI-40` is unambiguous (nct.md §1.2 rule 4).
value
    : sign? NUMBER                         # numberValue
    | sign? variable                       # variableValue
    | sign? LBRACK expr RBRACK             # bracketValue
    ;

sign : PLUS | MINUS ;

// ---------------------------------------------------------------- macro statements
statement
    : assignment                                           # assignStatement
    | GOTO expr                                            # gotoStatement
    | IF LBRACK condition RBRACK GOTO expr                 # ifGotoStatement
    | IF LBRACK condition RBRACK THEN? assignment          # ifThenStatement
    | WHILE LBRACK condition RBRACK DO NUMBER              # whileStatement
    | DO NUMBER                                            # doStatement
    | END NUMBER                                           # endStatement
    | PRINT_COMMAND                                        # printStatement
    | POPEN NUMBER?                                        # popenStatement
    | PCLOS NUMBER?                                        # pclosStatement
    | FOPEN NUMBER (P NUMBER | PATH)                       # fopenStatement
    | FCLOS                                                # fclosStatement
    ;

assignment : variable ASSIGN expr ;

condition : expr relation expr ;
relation  : EQ | NE | GT | GE | LT | LE ;

// ---------------------------------------------------------------- expressions (macro §3.1)
expr    : term (addOp term)* ;
addOp   : PLUS | MINUS | OR | XOR ;
term    : unary (mulOp unary)* ;
mulOp   : STAR | SLASH | AND | MOD ;
unary   : (PLUS | MINUS) unary | primary ;

primary
    : NUMBER                                                         # numberPrimary
    | variable                                                       # variablePrimary
    | LBRACK expr RBRACK                                             # bracketPrimary
    | function primary                                               # callPrimary
    | NOT primary                                                    # notPrimary
    | AXNUM LBRACK address RBRACK                                    # axnumPrimary
    | PRM LBRACK expr (COMMA expr)? RBRACK (SLASH LBRACK expr RBRACK)? # prmPrimary
    ;

function : SIN | COS | TAN | ASIN | ACOS | ATAN | SQRT | EXP | LN | ABS | FIX | FUP ;

variable
    : HASH NUMBER                          # numberedVariable
    | HASH LBRACK expr RBRACK              # indirectVariable
    | SYSTEM_NAME (LBRACK expr RBRACK)?    # namedVariable
    ;

// ---------------------------------------------------------------- lexer
// Keywords come first; longest match keeps `DO1` a keyword and `D1` an address, because an
// address always needs a value (digit, sign, `.`, `#`, `[`, `<`) after it.
GOTO  : 'GOTO' ;
IF    : 'IF' ;
THEN  : 'THEN' ;
WHILE : 'WHILE' ;
DO    : 'DO' ;
END   : 'END' ;
EQ : 'EQ' ;  NE : 'NE' ;  GT : 'GT' ;  GE : 'GE' ;  LT : 'LT' ;  LE : 'LE' ;
AND : 'AND' ;  OR : 'OR' ;  XOR : 'XOR' ;  MOD : 'MOD' ;  NOT : 'NOT' ;
SIN : 'SIN' ;  COS : 'COS' ;  TAN : 'TAN' ;  ASIN : 'ASIN' ;  ACOS : 'ACOS' ;  ATAN : 'ATAN' ;
SQRT : 'SQRT' ;  EXP : 'EXP' ;  LN : 'LN' ;  ABS : 'ABS' ;  FIX : 'FIX' ;  FUP : 'FUP' ;
AXNUM : 'AXNUM' ;  AX : 'AX' ;  PRM : 'PRM' ;
POPEN : 'POPEN' ;  PCLOS : 'PCLOS' ;  FOPEN : 'FOPEN' ;  FCLOS : 'FCLOS' ;

// DPRNT[...] / BPRNT[...]: free text with `#v[cd]` formats (macro §6); parsed by the builder.
PRINT_COMMAND : ('DPRNT' | 'BPRNT') '[' ( ~[[\]\n] | '[' ~[\]\n]* ']' )* ']' ;

A : 'A' ; B : 'B' ; C : 'C' ; D : 'D' ; E : 'E' ; F : 'F' ; G : 'G' ; H : 'H' ;
I : 'I' ; J : 'J' ; K : 'K' ; L : 'L' ; M : 'M' ; N : 'N' ; O : 'O' ; P : 'P' ;
Q : 'Q' ; R : 'R' ; S : 'S' ; T : 'T' ; U : 'U' ; V : 'V' ; W : 'W' ; X : 'X' ;
Y : 'Y' ; Z : 'Z' ;

NUMBER : DIGIT+ ('.' DIGIT*)? | '.' DIGIT+ ;
fragment DIGIT : [0-9] ;

SYSTEM_NAME : '#_' [A-Z0-9_]+ ;
HASH    : '#' ;
LBRACK  : '[' ;
RBRACK  : ']' ;
ASSIGN  : '=' ;
PLUS    : '+' ;
MINUS   : '-' ;
STAR    : '*' ;
SLASH   : '/' ;
COMMA   : ',' ;
PERCENT : '%' ;
PATH    : '<' ~[>\n]* '>' ;          // M98 <file>, G65 <file> (nct.md §5.1)

COMMENT : '(' ~[)]* ')' -> channel(HIDDEN) ;   // may span lines (nct.md §1.5)
WS      : [ \t\r\n]+ -> skip ;
