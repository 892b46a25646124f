// interp_block.vh: the two block words of rtl/interp, each one packed
// vector with named fields (a struct, in Verilog-2005): the LSB of every
// field as a function of the coordinate width W, the parameter of the
// module that includes this file. A field is read as v[BLK_CI +: W].
// Included inside a module, after W (no include guard: every module that
// uses it includes it). The C++ harness packs the host's block with the
// same offsets (tb/interp/core_harness.hpp, blk_*): keep them in step.
// A table: no one module uses every entry (waiver in rtl/verilator.vlt).

// The host's block, as wb_regs stages it and blk_prep takes it
// (wb_regs -> interp_core -> blk_prep; meaning of the fields: blk_prep.v).
// The mode bits come first, in the order of the BLK_MODE register.
localparam integer BLK_ARC = 0;             // 1: arc, 0: line
localparam integer BLK_CW = 1;              // arc: clockwise
localparam integer BLK_SXN = 2;             // line: X runs negative
localparam integer BLK_SYN = 3;             // line: Y runs negative
localparam integer BLK_Q = 4;               // 2 bits: arc, start quadrant
localparam integer BLK_K = 6;               // 3 bits: arc, quadrant crossings
localparam integer BLK_CI = 9;              // W bits: arc, start magnitude, inward axis
localparam integer BLK_CO = BLK_CI + W;     // W bits: arc, start magnitude, outward axis
localparam integer BLK_TI = BLK_CO + W;     // W bits: arc, end magnitude, inward axis of the end quadrant; line: |xe|
localparam integer BLK_TO = BLK_TI + W;     // W bits: arc, end magnitude, outward axis of the end quadrant; line: |ye|
localparam integer BLK_BITS = BLK_TO + W;   // 9 + 4 W

// The prepared block, as blk_prep writes it into the queue and interp_dp
// loads it (blk_prep -> move_fifo -> interp_dp; meaning: interp_dp.v).
// Two parts (interp_core queues each apart): the late part, bits
// [PRE_TI-1:0], from blk_prep's registers (the clock after the push),
// the early part, bits [PRE_BITS-1:PRE_TI], from the host's block itself
// (the push clock).
localparam integer PRE_FLAGS = 0;                // 8 bits: interp_dp's F_* order
localparam integer PRE_TI2 = PRE_FLAGS + 8;      // W + 2 bits: ti + 2 (arc) / ti - 2
localparam integer PRE_SUB = PRE_TI2 + W + 2;    // W + 1 bits: SUB
localparam integer PRE_TI = PRE_SUB + W + 1;     // W bits: inward target ti (end of the late part)
localparam integer PRE_TO = PRE_TI + W;          // W bits: outward target to
localparam integer PRE_ADD = PRE_TO + W;         // W + 1 bits: ADD
localparam integer PRE_CO = PRE_ADD + W + 1;     // W bits: outward magnitude
localparam integer PRE_CI = PRE_CO + W;          // W bits: inward magnitude
localparam integer PRE_K = PRE_CI + W;           // 3 bits: crossings
localparam integer PRE_Q = PRE_K + 3;            // 2 bits: quadrant
localparam integer PRE_SYN = PRE_Q + 2;          // line: Y runs negative
localparam integer PRE_SXN = PRE_SYN + 1;        // line: X runs negative
localparam integer PRE_CW = PRE_SXN + 1;         // arc: clockwise
localparam integer PRE_ARC = PRE_CW + 1;         // 1: arc
localparam integer PRE_BITS = PRE_ARC + 1;       // 7 W + 21
