// interp_core: block preparation, move queue and interpolation datapath.
//
//   push (raw block) -> blk_prep -> move_fifo -> interp_dp -> pulses
//
// One interpolation step per clock while i_cmd is high; consecutive queued
// blocks run back to back (the next block is loaded in the clock of the
// previous block's last pulse). i_abort drops the queue and the running
// move, like a reset of the interpolator alone. A block pushed while
// o_full is refused (nothing happens); a pushed block is in the queue
// (o_level) at once and can be loaded two clocks later (blk_prep's one
// stage, the late part's queue memory). i_blk need only be valid in the
// clock of i_push (blk_prep keeps what it needs).
`default_nettype none

module interp_core #(
    parameter integer W = 24,  // coordinate magnitude width (3..30)
    parameter integer QAW = 4  // log2 of the queue depth (blocks)
) (
    input  wire           i_clk,
    input  wire           i_rst,
    input  wire           i_abort,
    input  wire           i_cmd,
    // Block, as the host writes it (see blk_prep), one packed vector.
    input  wire           i_push,
    input  wire [4*W+8:0] i_blk,     // [BLK_BITS-1:0], interp_block.vh
    output wire           o_full,
    output wire [QAW+1:0] o_level,
    // Pulses and state (interp_dp).
    output wire           o_pulse,
    output wire           o_pulse_y,
    output wire           o_pulse_neg,
    output wire           o_pulse_last,
    output wire           o_busy,
    output wire [W-1:0]   o_xmag,
    output wire           o_xneg,
    output wire [W-1:0]   o_ymag,
    output wire           o_yneg,
    output wire [W+1:0]   o_d,
    output wire [1:0]     o_q,
    output wire [2:0]     o_k,
    output wire           o_arc
);

`include "interp_block.vh"

  localparam [QAW+1:0] DEPTH = {2'b01, {QAW{1'b0}}};  // memory depth

  reg full_q;
  wire push_ok = i_push & ~o_full;
  wire p_wr, p_wr_late;       // the early / late fields of a block are written
  wire [PRE_BITS-1:0] p_pre;  // prepared block, into the queue

  blk_prep #(.W(W)) u_prep (
      .i_clk(i_clk), .i_rst(i_rst | i_abort), .i_push(push_ok), .i_blk(i_blk),
      .o_wr(p_wr), .o_wr_late(p_wr_late), .o_pre(p_pre)
  );

  // The queue, in two parts: blk_prep gives a block's early fields (the
  // host's, ADD) in the push clock, a clock before the late ones (SUB, the
  // constants, the flags, from its registers), and each part has its
  // queue, written when its part comes, so no field waits in a register. Both are popped
  // together; the late queue is never ahead of the early one, so the head
  // is valid when the late queue's is. interp_block.vh orders the fields
  // so that each part is one range of the prepared block: the late part
  // below PRE_TI, the early part from it.
  localparam integer EW = PRE_BITS - PRE_TI;       // TI, TO, ADD, CO, CI, K, Q, SYN, SXN, CW, ARC
  localparam integer LW = PRE_TI;                  // FLAGS, TI2, SUB
  wire [EW-1:0] p_early = p_pre[PRE_TI +: EW];
  wire [LW-1:0] p_late = p_pre[0 +: LW];

  wire e_valid, l_valid, pop;
  wire [EW-1:0] h_early;
  wire [LW-1:0] h_late;
  wire [QAW+1:0] fifo_level;
  wire [QAW:0] mem_used;
  wire [QAW+1:0] unused_l_level;
  wire [QAW:0] unused_l_used;

  move_fifo #(.WIDTH(EW), .AW(QAW)) u_fifo (
      .i_clk(i_clk), .i_rst(i_rst), .i_flush(i_abort),
      .i_push(p_wr), .i_data(p_early),
      .i_pop(pop), .o_valid(e_valid), .o_data(h_early), .o_level(fifo_level), .o_used(mem_used)
  );

  move_fifo #(.WIDTH(LW), .AW(QAW)) u_fifo_late (
      .i_clk(i_clk), .i_rst(i_rst), .i_flush(i_abort),
      .i_push(p_wr_late), .i_data(p_late),
      .i_pop(pop), .o_valid(l_valid), .o_data(h_late), .o_level(unused_l_level), .o_used(unused_l_used)
  );

  // The late queue's head valid alone (one LUT input less before the
  // load decision): it implies the early one's (asserted below).
  wire head_valid = l_valid;
  wire [PRE_BITS-1:0] head = {h_early, h_late};

  // The level, the blocks in the early queue's memory and at its head
  // (fifo_level: the early part is written in the push clock), is a
  // counter: a block counts from the clock after its push to the clock of
  // its pop, so it changes by push_ok - pop alone (asserted equal below). A register, so no pointer
  // subtraction and no adder sits before a status read (issue 15: interp_top's
  // STATUS read, rptr -> used -> level -> the read multiplexer, ~9 ns).
  reg [QAW+1:0] level_q;
  always @(posedge i_clk) begin
    if (i_rst | i_abort) level_q <= {(QAW+2){1'b0}};
    else if (push_ok != pop) level_q <= pop ? level_q - 1'b1 : level_q + 1'b1;
  end
  assign o_level = level_q;
  wire [QAW+1:0] unused_level = fifo_level;
  wire [QAW:0] unused_used = mem_used;

  // Full counts the blocks like the level (the early queue holds a block
  // from the clock after its push on). It is a register: full when the
  // blocks committed to the memory after this clock (the memory's,
  // mem_used = level_q - e_valid, and push_ok), not
  // counting the one the datapath may take, fill it (never too
  // optimistic). From the level counter: no pointer subtraction (asserted
  // equal to the count from the pointers below).
  // committed >= DEPTH, committed = level_q + push_ok - e_valid, written
  // as three compares of the counter (no adder).
  wire full_next = (level_q > DEPTH) | ((level_q == DEPTH) & (push_ok | ~e_valid))
                 | ((level_q == DEPTH - 1'b1) & push_ok & ~e_valid);
  always @(posedge i_clk) begin
    if (i_rst | i_abort) full_q <= 1'b0;
    else full_q <= full_next;
  end
  assign o_full = full_q;

  interp_dp #(.W(W)) u_dp (
      .i_clk(i_clk), .i_rst(i_rst | i_abort), .i_cmd(i_cmd),
      .i_valid(head_valid), .o_ready(pop), .i_pre(head),
      .o_pulse(o_pulse), .o_pulse_y(o_pulse_y), .o_pulse_neg(o_pulse_neg),
      .o_pulse_last(o_pulse_last), .o_busy(o_busy),
      .o_xmag(o_xmag), .o_xneg(o_xneg), .o_ymag(o_ymag), .o_yneg(o_yneg),
      .o_d(o_d), .o_q(o_q), .o_k(o_k), .o_arc(o_arc)
  );

`ifdef FORMAL
  // The late part of a block is written a clock after its early part and
  // both queues are popped together: whenever the late head is valid, the
  // early head is, and holds the same block.
  reg past_valid_f;
  initial past_valid_f = 1'b0;
  always @(posedge i_clk) past_valid_f <= 1'b1;
  always @(*) begin
    if (past_valid_f) assert(!l_valid || e_valid);
  end
  // The level counter is the count it stands for, and the full flag's
  // next value, from it, is the test of the memory's count.
  always @(*) begin
    if (past_valid_f) begin
      assert(level_q == fifo_level);
      assert(full_next == ({1'b0, mem_used} + {{(QAW+1){1'b0}}, push_ok} >= DEPTH));
    end
  end
`endif

endmodule
