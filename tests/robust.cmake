# Bad input end to end (tests/corpus/nct/robust): each test runs the gcx command line and checks
# the exit code and the located diagnostic. Runaways use lowered limits; docs/limits.md gives the
# defaults and how long each runaway takes to reach them.
set(ROBUST ${CMAKE_SOURCE_DIR}/tests/corpus/nct/robust)

# gcx_robust(NAME EXIT STDERR CMD FILE [ARGS...])
function(gcx_robust name exit stderr cmd file)
  add_test(NAME robust.${name} COMMAND ${CMAKE_COMMAND} -DGCX=$<TARGET_FILE:gcx> -DCMD=${cmd}
    -DFILE=${file} "-DARGS=${ARGN}" -DEXPECT_EXIT=${exit} "-DEXPECT_STDERR=${stderr}"
    -P ${CMAKE_CURRENT_SOURCE_DIR}/support/expect_exit.cmake)
endfunction()

# gcx_robust_stdout_full(NAME CMD FILE [ARGS...]): standard output on a full device is exit 2
function(gcx_robust_stdout_full name cmd file)
  add_test(NAME robust.${name} COMMAND ${CMAKE_COMMAND} -DGCX=$<TARGET_FILE:gcx> -DCMD=${cmd}
    -DFILE=${file} "-DARGS=${ARGN}" -DEXPECT_EXIT=2 -DSTDOUT_FILE=/dev/full
    "-DEXPECT_STDERR=standard output: cannot write: No space left on device"
    -P ${CMAKE_CURRENT_SOURCE_DIR}/support/expect_exit.cmake)
endfunction()

# 1. deep nesting: a located error before the parser recurses, from every command that parses
gcx_robust(nested_brackets_check 1 "nested_brackets.nct:1:68: error: expression nested deeper than 64 levels (brackets, signs, functions) [GCX017]" check ${ROBUST}/nested_brackets.nct)
gcx_robust(nested_brackets_run 1 "nested_brackets.nct:1:68: error: expression nested deeper than 64 levels" run ${ROBUST}/nested_brackets.nct)
gcx_robust(nested_brackets_fmt 1 "nested_brackets.nct:1:68: error: expression nested deeper" fmt ${ROBUST}/nested_brackets.nct)
# a character the lexer refuses inside deep brackets: reported before the parser recurses (found by fuzz)
gcx_robust(nested_brackets_bad_character 1 "nested_brackets_bad_character.nct:1:5004: error: unexpected character '_' [2064]" check ${ROBUST}/nested_brackets_bad_character.nct)

# 2. runaways: each kind stops with its limit, which the message names with the flag
gcx_robust(while_runaway 1 "while_runaway.nct:4:1: error: loop DO1 repeated more than 1000 times (exceeded --max-jumps 1000; raise it with --max-jumps N) [GCX040]" run ${ROBUST}/while_runaway.nct --max-jumps 1000)
gcx_robust(m99_main_runaway 1 "m99_main_runaway.nct:2:1: error: M99 in the main program looped more than 1000 times (exceeded --max-jumps 1000; raise it with --max-jumps N) [GCX040]" run ${ROBUST}/m99_main_runaway.nct --max-jumps 1000)
gcx_robust(m99_repeat_runaway 1 "O7001.nct:3:1: error: O7001 (M98 P7001) repeated more than 1000 times by its L count (exceeded --max-jumps 1000; raise it with --max-jumps N) [GCX040]" run ${ROBUST}/m99_repeat_runaway.nct --max-jumps 1000)
gcx_robust(m98_repeat_runaway 1 "O7002.nct:3:1: error: O7002 (M98 P7002) repeated more than 1000 times by its L count" run ${ROBUST}/m98_repeat_runaway.nct --max-jumps 1000)
gcx_robust(g65_repeat_runaway 1 "O7002.nct:3:1: error: O7002 (G65 P7002) repeated more than 1000 times by its L count" run ${ROBUST}/g65_repeat_runaway.nct --max-jumps 1000)
gcx_robust(goto_runaway 1 "goto_runaway.nct:2:1: error: more than 1000 backward jumps: runaway loop (GOTO N1; exceeded --max-jumps 1000; raise it with --max-jumps N) [GCX040]" run ${ROBUST}/goto_runaway.nct --max-jumps 1000)
gcx_robust(drill_repeat_runaway 1 "drill_repeat_runaway.nct:2:1: error: more than 1000 moves beyond one a block (cycles, repeats, arc turns): exceeded --max-moves 1000; raise it with --max-moves N [GCX043]" run ${ROBUST}/drill_repeat_runaway.nct --max-moves 1000)
gcx_robust(blocks_runaway 1 "blocks_runaway.nct:4:1: error: more than 3 blocks executed: is this an endless loop? (exceeded --max-blocks 3; raise it with --max-blocks N) [GCX041]" run ${ROBUST}/blocks_runaway.nct --max-blocks 3)
# 3. output amplification: L turns count as moves (default limit, stops before writing), and
# the bytes of all outputs are bounded
gcx_robust(arc_turns_runaway 1 "arc_turns_runaway.nct:2:1: error: more than 10000000 moves beyond one a block (cycles, repeats, arc turns): exceeded --max-moves 10000000; raise it with --max-moves N [GCX043]" expand ${ROBUST}/arc_turns_runaway.nct --to canonical)
gcx_robust(spiral_output_size 1 "spiral_output.nct:2:1: error: the output exceeded --max-output 10240 bytes; raise it with --max-output N [GCX044]" expand ${ROBUST}/spiral_output.nct --to canonical --max-output 10k)
gcx_robust(print_output_size 1 "print_output.nct:4:1: error: the output exceeded --max-output 10240 bytes; raise it with --max-output N [GCX044]" run ${ROBUST}/print_output.nct --max-output 10k --print ${CMAKE_CURRENT_BINARY_DIR}/robust_print.txt)

# 4. values that are not finite or not writable never reach an output
gcx_robust(exp_overflow 1 "exp_overflow.nct:1:6: error: the result is not a finite number (beyond the range of a double) [GCX045]" expand ${ROBUST}/exp_overflow.nct --to nct)
gcx_robust(inf_minus_inf 1 "inf_minus_inf.nct:2:4: error: the result is not a finite number" run ${ROBUST}/inf_minus_inf.nct)
gcx_robust(product_overflow 1 "product_overflow.nct:1:4: error: the result is not a finite number" run ${ROBUST}/product_overflow.nct)
gcx_robust(tiny_feed 1 "tiny_feed.nct:1:1: error: feed 9.85968e-305 is too small to write (below 0.000001) [GCX045]" expand ${ROBUST}/tiny_feed.nct --to nct)
gcx_robust(huge_coordinate 1 "huge_coordinate.nct:1:1: error: the move reaches a coordinate or feed of magnitude 1e9 or more (machine frame, mm) [GCX045]" expand ${ROBUST}/huge_coordinate.nct --to canonical)
gcx_robust(huge_coordinate_stats 1 "huge_coordinate.nct:1:1: error: the move reaches a coordinate" run ${ROBUST}/huge_coordinate.nct --stats)
gcx_robust(work_offset_inf 1 "work_offset_inf.nct:1:7: error: the result is not a finite number" expand ${ROBUST}/work_offset_inf.nct --to canonical)
gcx_robust(work_offset_huge 1 "work_offset_huge.nct:2:1: error: the move reaches a coordinate" expand ${ROBUST}/work_offset_huge.nct --to canonical)
gcx_robust(g10_offset_inf 1 "g10_offset_inf.nct:1:13: error: the result is not a finite number" expand ${ROBUST}/g10_offset_inf.nct --to canonical)

# 5. the alarm number is range-checked before it becomes an int
gcx_robust(alarm_number_huge 1 "alarm_number_huge.nct:1:1: error: #3000 = 99999999999 is out of range: a message number is 0-999 [2002]" run ${ROBUST}/alarm_number_huge.nct)
gcx_robust(alarm_number_inf 1 "alarm_number_inf.nct:1:7: error: the result is not a finite number" run ${ROBUST}/alarm_number_inf.nct)
gcx_robust(message_number_negative 1 "message_number_negative.nct:1:1: error: #3006 = -1 is out of range: a message number is 0-999 [2002]" run ${ROBUST}/message_number_negative.nct)

# 6. program paths stay inside the program's folder and the --lib folders
gcx_robust(path_traversal 1 "path_traversal.nct:1:5: error: program <../../../../../../../../../../../../etc/passwd> lies outside the program's folder and the --lib folders; add its folder with --lib DIR [GCX046]" run ${ROBUST}/path_traversal.nct)
gcx_robust(absolute_path 1 "absolute_path.nct:1:5: error: program </etc/hostname> lies outside" run ${ROBUST}/absolute_path.nct)
gcx_robust(path_within_folder 0 "" expand ${ROBUST}/path_within.nct --to canonical)

# 7. every write is checked: exit 2, the reason named
gcx_robust(expand_to_full_device 2 "/dev/full: cannot write: No space left on device" expand ${ROBUST}/plain.nct --to canonical -o /dev/full)
gcx_robust(expand_nct_to_full_device 2 "/dev/full: cannot write: No space left on device" expand ${ROBUST}/plain.nct --to nct -o /dev/full)
gcx_robust(fmt_to_full_device 2 "/dev/full: cannot write: No space left on device" fmt ${ROBUST}/plain.nct -o /dev/full)
gcx_robust(plot_to_full_device 2 "/dev/full: cannot write: No space left on device" plot ${ROBUST}/plain.nct -o /dev/full)
gcx_robust(trace_to_full_device 2 "/dev/full: cannot write: No space left on device" run ${ROBUST}/plain.nct --trace /dev/full)
gcx_robust(print_to_missing_folder 2 "/nonexistent/print.txt: cannot write: No such file or directory" run ${ROBUST}/plain.nct --print /nonexistent/print.txt)
gcx_robust(print_to_full_device 2 "/dev/full: cannot write: No space left on device" run ${ROBUST}/print_output.nct --print /dev/full)
gcx_robust_stdout_full(expand_stdout_full expand ${ROBUST}/plain.nct --to canonical)
gcx_robust_stdout_full(fmt_stdout_full fmt ${ROBUST}/plain.nct)
gcx_robust_stdout_full(run_stats_stdout_full run ${ROBUST}/plain.nct --stats)
gcx_robust_stdout_full(check_stdout_full check ${ROBUST}/plain.nct)

# 8. smaller defects
gcx_robust(dprnt_padding 1 "dprnt_padding.nct:1:10: error: print format [99999999]: c integer and d fraction digits need 0 < c+d < 16 [2002]" run ${ROBUST}/dprnt_padding.nct)
gcx_robust(dprnt_sixteen_digits 1 "dprnt_sixteen_digits.nct:1:10: error: print format [88]" check ${ROBUST}/dprnt_sixteen_digits.nct)
gcx_robust(g95_s0 1 "g95_s0.nct:1:1: error: feed per revolution (G95) with the spindle speed S0: the move would never end [GCX047]" run ${ROBUST}/g95_s0.nct --stats)
gcx_robust(do_huge 1 "do_huge.nct:1:12: error: DO99999999 is out of range: loop numbers are 1-3 [2002]" check ${ROBUST}/do_huge.nct)
gcx_robust(variable_number_huge 1 "variable_number_huge.nct:1:1: error: #99999999999999999999 does not exist: variable numbers have at most 12 digits [NCTX01]" check ${ROBUST}/variable_number_huge.nct)
gcx_robust(directory_as_program 1 "directory_program.nct:1:5: error: program O7012.nct not found next to directory_program.nct or in the library folders [NCTX07]" run ${ROBUST}/directory_program.nct)
gcx_robust(setup_missing 2 "missing.json: cannot read the setup file" run ${ROBUST}/plain.nct --setup ${ROBUST}/missing.json)
gcx_robust(max_errors_zero 2 "--max-errors: must be a whole number of 1 or more, not '0'" check ${ROBUST}/plain.nct --max-errors 0)
gcx_robust(max_jumps_negative 2 "--max-jumps: must be a whole number of 1 or more, not '-1'" run ${ROBUST}/plain.nct --max-jumps -1)
gcx_robust(max_output_zero 2 "--max-output: must be a whole number of 1 or more, not '0'" run ${ROBUST}/plain.nct --max-output 0)
gcx_robust(divide_by_zero_without_variables 1 "divide_by_zero_no_macro.nct:1:6: error: attempt to divide by zero [2093]" run ${ROBUST}/divide_by_zero_no_macro.nct)
gcx_robust(lone_cr_hint 1 "lone_cr.nct:1:6: warning: carriage return without a line feed: blocks end at LF; a file with CR-only line ends (old Macintosh) must be converted to LF or CR LF [GCXW04]" check ${ROBUST}/lone_cr.nct)
gcx_robust(dwell_huge 1 "dwell_huge.nct:1:1: error: the block's value 4.60461e+299 (dwell time, speed, tool or code) is out of range: 1e9 or more [GCX045]" expand ${ROBUST}/dwell_huge.nct --to canonical)
gcx_robust(long_operator_chain 1 "long_operator_chain.nct:1:2005: error: more than 1000 operators in one block [GCX017]" run ${ROBUST}/long_operator_chain.nct)
gcx_robust(goto_huge 1 "goto_huge.nct:2:1: error: block N1.01423e+304 not found: block numbers are 1-99999999 [2125]" run ${ROBUST}/goto_huge.nct)
# --max-moves bounds what a block adds beyond its own first move: a plain program of any length
# runs under the smallest limit, while a cycle's holes and passes count (docs/limits.md)
gcx_robust(max_moves_plain_program_runs 0 "" run ${ROBUST}/plain_moves.nct --max-moves 1)
gcx_robust(max_moves_cycle_holes_count 1 "drill_two_holes.nct:2:1: error: more than 1 moves beyond one a block (cycles, repeats, arc turns): exceeded --max-moves 1; raise it with --max-moves N [GCX043]" run ${ROBUST}/drill_two_holes.nct --max-moves 1)
