// FMS-3000 block grammar (fms3000.md §1.1, §1.2, §6.3).
//
// One parse = one NC block. The block reader (src/front/block_reader) has already
//  * split the file into blocks at LF, dropping the CR of CR LF (fms3000.md §1.1),
//  * checked the block length (254 characters with CR LF),
//  * kept letters as written: only `rem` and `endcont` are lower case, and the front end
//    (dialects/fms3000/reader) takes `rem` lines, `endcont` and macro-language lines before
//    this grammar runs.
// So this grammar sees NC blocks: an optional N and words in any order. Blanks between words
// are allowed; a blank inside a number is not (the number ends there). There are no comments,
// no block skip, no `%` and no expressions (the macro language is not documented, §6.4).
grammar FMS3000;

block : sequenceNumber? word* EOF ;

// "N" with up to 7 digits; a bare "N" (`NG90`, OCR or not) is tolerated (§6.3, §10 Q12)
sequenceNumber : N NUMBER? ;

word : address sign? NUMBER ;

// Longest match: `DR5` is DR=5, `GG1` is GG=1, `LIMS1100` is LIMS=1100 (§1.1). No exponent:
// `X1E3` is X1 and E3 (§1.2).
address
    : LIMS | DR | DX | DY | DZ | GG
    | A | B | C | D | E | F | G | H | I | J | K | L | M
    | P | Q | R | S | T | U | V | W | X | Y | Z
    ;

sign : PLUS | MINUS ;

// ---------------------------------------------------------------- lexer
LIMS : 'LIMS' ;
DR : 'DR' ;  DX : 'DX' ;  DY : 'DY' ;  DZ : 'DZ' ;
GG : 'GG' ;

A : 'A' ; B : 'B' ; C : 'C' ; D : 'D' ; E : 'E' ; F : 'F' ; G : 'G' ; H : 'H' ;
I : 'I' ; J : 'J' ; K : 'K' ; L : 'L' ; M : 'M' ; N : 'N' ; P : 'P' ;
Q : 'Q' ; R : 'R' ; S : 'S' ; T : 'T' ; U : 'U' ; V : 'V' ; W : 'W' ; X : 'X' ;
Y : 'Y' ; Z : 'Z' ;

// value = [+|-] (digits [. [digits]] | . digits)  (§1.2)
NUMBER : DIGIT+ ('.' DIGIT*)? | '.' DIGIT+ ;
fragment DIGIT : [0-9] ;

PLUS  : '+' ;
MINUS : '-' ;

WS : [ \t]+ -> skip ;
