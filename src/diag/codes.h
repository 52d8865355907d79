// Stable diagnostic codes. Where the NCT manual numbers an alarm we use its number (nct.md §1.11,
// nct-macro.md §3.4); NCTXnn are the spec's numbers for errors the manual describes without one;
// GCXnnn are gcx's own (input files, limits, static checks the manual leaves unnumbered).
// docs/diagnostics.md lists them all; never renumber a code once released.
#pragma once

namespace gcx::diag::code {

// --- manual alarm numbers
inline constexpr const char* DataOutOfRange = "2002";
inline constexpr const char* MissingData = "2004";
inline constexpr const char* ForbiddenAddress = "2017";
inline constexpr const char* SyntaxError = "2064";
inline constexpr const char* IllegalIncremental = "2097";
inline constexpr const char* WhileWithoutDo = "2110";
inline constexpr const char* RightBracketNotFound = "2121";
inline constexpr const char* BlockNotFound = "2125";

// --- spec numbers (nct-macro.md §12)
inline constexpr const char* LoopPairing = "NCTX06";
inline constexpr const char* VariableNotAllowed = "NCTX10";
inline constexpr const char* WriteProtected = "NCTX02";
inline constexpr const char* CallNesting = "NCTX03";
inline constexpr const char* ProgramNotFound = "NCTX07";
inline constexpr const char* MissingReturn = "NCTX08";
inline constexpr const char* AtanTwoArgs = "NCTW02";

// --- gcx: input files
inline constexpr const char* CannotRead = "GCX001";
inline constexpr const char* EmptyProgram = "GCX002";
inline constexpr const char* BinaryFile = "GCX003";
inline constexpr const char* InvalidUtf8 = "GCX004";
inline constexpr const char* BlockTooLong = "GCX005";
inline constexpr const char* UnterminatedComment = "GCX006";
inline constexpr const char* MisplacedPercent = "GCX007";
inline constexpr const char* InvalidEncodedByte = "GCX008"; // not valid in the --encoding chosen
inline constexpr const char* TooManyErrors = "GCX009";
// --- gcx: static block checks
inline constexpr const char* RepeatedAddress = "GCX011";
inline constexpr const char* ModalGroupConflict = "GCX012";
inline constexpr const char* UnknownGCode = "GCX013";
inline constexpr const char* ConflictingMCodes = "GCX014";
inline constexpr const char* IncrementalNotAllowed = "GCX015";
inline constexpr const char* TooManyDigits = "GCX016";
inline constexpr const char* ExpressionTooDeep = "GCX017";
// --- gcx: warnings
inline constexpr const char* SignAlias = "GCXW01";
inline constexpr const char* SkipLevelNine = "GCXW02";
inline constexpr const char* StrayParen = "GCXW03";
inline constexpr const char* LoneCarriageReturn = "GCXW04";
inline constexpr const char* LongBlock = "GCXW05";        // longer than the dialect's manual allows
inline constexpr const char* SkipWithoutTouch = "GCXW06"; // a skip move without a probe model

// --- machine: alarms the manual numbers (nct.md §3)
inline constexpr const char* MirrorWithTransform = "2001";
inline constexpr const char* ArcRadiusMismatch = "2012";
inline constexpr const char* ArcDefinition = "2015";
// --- machine: cutter radius compensation (nct.md §3.17, docs/compensation.md)
inline constexpr const char* CompCancelInArc = "2043";      // G40 in a G2/G3 block
inline constexpr const char* CompNoIntersection = "2047";   // inner corner, offsets do not meet
inline constexpr const char* CompInterference = "2049";     // compensated move against the path
inline constexpr const char* CompBufferFull = "2090";       // no plane motion within the look-ahead
inline constexpr const char* CompRadiusTooLarge = "GCX070"; // tool radius >= an inner arc's
inline constexpr const char* CompPlaneChange = "GCX071";    // G17/G18/G19 while compensating
inline constexpr const char* CompStartInArc = "GCX072";     // G41/G42 start-up in G2/G3
inline constexpr const char* CompNoRegister = "GCX073";     // D names no radius register
inline constexpr const char* CompNegativeRadius = "GCX090"; // nose radius + D below 0 (WL4)
inline constexpr const char* ThreadSequenceOpen = "GCX091"; // a G32 sequence not ended by G0-G3
inline constexpr const char* ThreadSequenceNoStop = "GCXW26";       // its last move without G9
inline constexpr const char* SurfaceSpeedSwitchWithoutS = "GCX092"; // G96<->G97 without S
// --- machine: automatic contour geometry (nct.md §4)
inline constexpr const char* ChamferAndRounding = "2082"; // ,C and ,R in one block
inline constexpr const char* IllegalChamfer = "2085";     // no plane element before or after
inline constexpr const char* ChamferTooBig = "GCX074";    // does not fit on the elements
inline constexpr const char* AngleLine = "GCX075";        // ,A outside a one-coordinate G0/G1
inline constexpr const char* CompOnlyCode = "GCX076";     // G38/G39 without G41/G42
// intersection calculations (nct.md §4.3)
inline constexpr const char* IntersectionElement = "GCX077"; // no element to intersect with
inline constexpr const char* IntersectionChoice = "GCX078";  // two points and no Q to choose
inline constexpr const char* CornerArcBlock = "GCX079";      // G39 with motion words or a bad I J K
// --- gcx: execution
inline constexpr const char* NotImplemented = "GCX030";
inline constexpr const char* UnknownGCodeAtRun = "GCX031";
inline constexpr const char* MCodeWithoutMotion = "GCX032";
inline constexpr const char* UnequalArcScaling = "GCX033";
inline constexpr const char* TransformNesting = "GCX034";
inline constexpr const char* DwellWithoutP = "GCX035";
inline constexpr const char* ExpressionNotExpanded = "GCX036";
inline constexpr const char* ArcZeroRadius = "GCX037";
inline constexpr const char* EndWithoutM30 = "GCX038";
inline constexpr const char* SkipUnderCompensation = "GCX039"; // a skip move (G32) under comp
// --- gcx: the macro pass
inline constexpr const char* RunawayLoop = "GCX040";
inline constexpr const char* TooManyBlocks = "GCX041";
inline constexpr const char* TooManyMoves = "GCX043";          // --max-moves
inline constexpr const char* OutputTooLarge = "GCX044";        // --max-output
inline constexpr const char* ValueOutOfRange = "GCX045";       // not finite, or not writable
inline constexpr const char* PathOutsideFolders = "GCX046";    // M98 <../x>, an absolute path
inline constexpr const char* FeedPerRevolutionAtS0 = "GCX047"; // G95 move, spindle speed 0
inline constexpr const char* ThreadAtRapid = "GCX048";         // a one-block thread (G33) under G0
inline constexpr const char* ParameterMissing = "NCTX11";
// --- WL4 (wl4.md)
inline constexpr const char* Wl4Syntax = "GCX060";           // a WL4 block that does not parse
inline constexpr const char* Wl4CallWord = "GCX061";         // L not nn or nnpp, or pp = 00
inline constexpr const char* Wl4DuplicateLabel = "GCX062";   // a label twice in one program
inline constexpr const char* Wl4ProgramName = "GCX063";      // a %name longer than 80
inline constexpr const char* Wl4FanucComment = "GCXW20";     // `(` where a word would start
inline constexpr const char* Wl4WholeMillimetres = "GCXW21"; // X1030 is 1030 mm
inline constexpr const char* Wl4FanucReturnLevel = "GCXW22"; // G98/G99
inline constexpr const char* Wl4FanucCall = "GCXW23";        // M98 is no call
inline constexpr const char* ErrorStop = "GCX064";      // a block that jumps to itself: %1's stops
inline constexpr const char* SystemReadOnly = "GCX065"; // WL4 #100 and up are read-only
inline constexpr const char* Wl4ThreadNotExpressible = "GCX066";   // G32/G33 phase, lead change
inline constexpr const char* Wl4ReturnInMain = "GCX067";           // M99 in the main program
inline constexpr const char* Wl4ProbeWithoutTouch = "GCXW24";      // G38: no probe model
inline constexpr const char* Wl4AbsoluteAndIncremental = "GCX068"; // X with U in one block
inline constexpr const char* Wl4TooManyLabels = "GCX069";          // over 127 labels
inline constexpr const char* CompWithoutPlaneMotion = "GCXW25";    // no plane motion under G41/G42

// --- gcx: setup file (--setup FILE, src/machine/setup)
inline constexpr const char* SetupNotJson = "GCX020";
inline constexpr const char* SetupUnknownKey = "GCX021";
inline constexpr const char* SetupWrongType = "GCX022";
inline constexpr const char* SetupBadValue = "GCX023";
inline constexpr const char* SetupCannotRead = "GCX024";

// --- macro evaluation (nct-macro.md §2.2, §2.6, §3.2-§3.4, §12)
inline constexpr const char* DivideByZero = "2093";
inline constexpr const char* TanDomain = "2116";
inline constexpr const char* ArcDomain = "2117";
inline constexpr const char* LogDomain = "2118";
inline constexpr const char* SqrtNegative = "2122";
inline constexpr const char* BitOperandRange = "2129";
inline constexpr const char* UndefinedVariable = "NCTX01";
inline constexpr const char* AddressValueRange = "NCTX04";

// --- macro variables (nct-macro.md §2.7, §2.8)
inline constexpr const char* ReadOnlyVariable = "2161";
inline constexpr const char* BitValueRange = "2092";
inline constexpr const char* VacantToSystem = "NCTX05";
inline constexpr const char* RuntimeOnlyVariable = "NCTW01";

// --- cycles (cycles.md §7): drilling-cycle data and machine support
inline constexpr const char* CycleNoData = "2053";        // no bottom point or R point
inline constexpr const char* CycleNoOrientation = "2137"; // G76 without spindle orientation
inline constexpr const char* CycleNotIndexable = "2138";  // G84.2/G84.3: spindle not indexable
inline constexpr const char* CycleQMissing = "CYC-Q-MISSING";
inline constexpr const char* CycleQNegative = "CYC-Q-NEGATIVE";
inline constexpr const char* CycleLRange = "CYC-L-RANGE";
inline constexpr const char* CycleCylindrical = "CYC-CYLINDRICAL";      // in G7.1 (no number given)
inline constexpr const char* CycleSpindleDirection = "CYC-SPINDLE-DIR"; // warning
inline constexpr const char* CycleRBeyondBottom = "CYC-R-BEYOND-BOTTOM"; // rapid to R passes Z
inline constexpr const char* CycleRadiusComp = "CYC-RADCOMP";            // warning (§9 Q-20)
// pocket-milling macro cycle G65 P9999 (§5): MACRO ERROR n as the #3000=n alarm 4000+n [D]
inline constexpr const char* PocketMacroError1 = "4001"; // MACRO ERROR 1: data not given
inline constexpr const char* PocketMacroError2 = "4002"; // MACRO ERROR 2: sizes
inline constexpr const char* PocketMacroMissing = "CYC-POCKET-MACRO-MISSING"; // no O9999

// --- cycles (cycles.md §7): turning cycles G70.7-G79.7 (§4)
inline constexpr const char* CyclePQNotFound = "CYC-PQ-NOTFOUND";     // P/Q missing, no such N
inline constexpr const char* CycleNsMode = "CYC-NS-MODE";             // ns block without G0/G1
inline constexpr const char* CycleNonMonotonic = "CYC-NONMONOTONIC";  // type-I contour
inline constexpr const char* CycleContourCommand = "CYC-CONTOUR-CMD"; // forbidden in ns..nf
inline constexpr const char* CycleType2 = "CYC-TYPE2-UNSUPPORTED";    // G71.7/G72.7 type II
inline constexpr const char* CycleContourDegenerate = "CYC-CONTOUR-DEGENERATE"; // nothing to cut
inline constexpr const char* CycleParam = "CYC-PARAM";          // a bad cycle parameter
inline constexpr const char* ThreadSpecification = "2021";      // G78.7/G76.7 lead <= 0
inline constexpr const char* CycleThreadCss = "CYC-THREAD-CSS"; // warning: threading in G96
inline constexpr const char* KeptContourLost = "GCX042"; // --keep cycles: a contour did not survive

// --- gcx equiv: reading RS274/NGC (docs/equivalence.md)
inline constexpr const char* NeedsRs274 = "GCX050";  // full LinuxCNC without rs274 installed
inline constexpr const char* Rs274Failed = "GCX051"; // rs274 rejected the program or its output

// --- FMS-3000 (fms3000.md)
inline constexpr const char* FmsMacroUnsupported = "FMSX01"; // СПЦП statement (§6.4, §10 Q1)
inline constexpr const char* FmsUnusedE = "GCXW10";          // E without G04 or a cycle (§1.2)
inline constexpr const char* FmsFanucHabit = "GCXW11"; // a Fanuc spelling with another meaning (§9)
inline constexpr const char* FmsCycleParameters = "FMSX02"; // cycle words wrong (§5, 001:3912-3975)
inline constexpr const char* FmsCallAndEnd = "FMSX03";      // P with M02/M30/M98 (§1.4, §10 Q21)
inline constexpr const char* FmsPolarRule = "FMSX04"; // G36 polar rules (§3.11, 001:3856-3859)
inline constexpr const char* FmsProfile = "FMSX05";   // G164/G165 profile wrong (001:3903-3975)
inline constexpr const char* FmsMotionCodeWords = "FMSX06"; // G27 without axes or with I J K
inline constexpr const char* FmsProgramRule = "FMSX07";     // end M codes, M99 with P, two calls
inline constexpr const char* FmsDependentAxes = "GCXW12";   // G45: dependent axes not modelled

// --- gcx translate between dialects (docs/translation.md)
inline constexpr const char* TranslateNoCode = "GCX080"; // the target has no code for this meaning
inline constexpr const char* TranslateValue = "GCX081";  // a value outside the target's format

} // namespace gcx::diag::code
