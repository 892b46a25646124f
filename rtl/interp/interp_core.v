// interp_core: block preparation, move queue and interpolation datapath.
//
//   push (raw block) -> blk_prep -> move_fifo -> interp_dp -> pulses
//
// One interpolation step per clock while i_cmd is high; consecutive queued
// blocks run back to back (the next block is loaded in the clock of the
// previous block's last pulse). i_abort drops the queue and the running
// move, like a reset of the interpolator alone. A block pushed while
// o_full is refused (nothing happens); a pushed block is in the queue
// (o_level) at once and can be loaded three clocks later.
`default_nettype none

module interp_core #(
    parameter integer W = 24,  // coordinate magnitude width (3..30)
    parameter integer QAW = 4  // log2 of the queue depth (blocks)
) (
    input  wire           i_clk,
    input  wire           i_rst,
    input  wire           i_abort,
    input  wire           i_cmd,
    // Block, as the host writes it (see blk_prep).
    input  wire           i_push,
    input  wire           i_arc,
    input  wire           i_cw,
    input  wire           i_sxn,
    input  wire           i_syn,
    input  wire [1:0]     i_q,
    input  wire [2:0]     i_k,
    input  wire [W-1:0]   i_xs,
    input  wire [W-1:0]   i_ys,
    input  wire [W-1:0]   i_xe,
    input  wire [W-1:0]   i_ye,
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

  localparam integer BW = 8 * W + 27;  // prepared block width
  localparam [QAW+1:0] DEPTH = {2'b01, {QAW{1'b0}}};  // memory depth

  reg full_q;
  wire push_ok = i_push & ~o_full;
  wire p_wr, p_arc, p_cw, p_sxn, p_syn;
  wire [1:0] p_inflight;
  wire [1:0] p_q;
  wire [2:0] p_k;
  wire [W-1:0] p_ci, p_co;
  wire [W:0] p_sub, p_add;
  wire [W+1:0] p_ti1, p_ti2, p_tim1, p_to2;
  wire [7:0] p_flags;

  blk_prep #(.W(W)) u_prep (
      .i_clk(i_clk), .i_rst(i_rst | i_abort), .i_push(push_ok),
      .i_arc(i_arc), .i_cw(i_cw), .i_sxn(i_sxn), .i_syn(i_syn), .i_q(i_q), .i_k(i_k),
      .i_xs(i_xs), .i_ys(i_ys), .i_xe(i_xe), .i_ye(i_ye),
      .o_inflight(p_inflight), .o_wr(p_wr),
      .o_arc(p_arc), .o_cw(p_cw), .o_sxn(p_sxn), .o_syn(p_syn),
      .o_q(p_q), .o_k(p_k), .o_ci(p_ci), .o_co(p_co), .o_sub(p_sub), .o_add(p_add),
      .o_ti1(p_ti1), .o_ti2(p_ti2), .o_tim1(p_tim1), .o_to2(p_to2), .o_flags(p_flags)
  );

  wire [BW-1:0] wdata = {p_arc, p_cw, p_sxn, p_syn, p_q, p_k, p_ci, p_co,
                         p_sub, p_add, p_ti1, p_ti2, p_tim1, p_to2, p_flags};

  wire head_valid, pop, unused_mem_full;  // full is decided below, with blocks in flight
  wire [BW-1:0] head;
  wire [QAW+1:0] fifo_level;
  wire [QAW:0] mem_used;

  move_fifo #(.WIDTH(BW), .AW(QAW)) u_fifo (
      .i_clk(i_clk), .i_rst(i_rst), .i_flush(i_abort),
      .i_push(p_wr), .i_data(wdata), .o_full(unused_mem_full),
      .i_pop(pop), .o_valid(head_valid), .o_data(head), .o_level(fifo_level), .o_used(mem_used)
  );

  // Full counts the blocks still in preparation; so does the level. It is
  // a register: the blocks committed to the memory after this clock, not
  // counting the one the datapath may take (never too optimistic).
  wire [QAW+1:0] committed = {1'b0, mem_used} + {{QAW{1'b0}}, p_inflight};
  always @(posedge i_clk) begin
    if (i_rst | i_abort) full_q <= 1'b0;
    else full_q <= (committed + {{(QAW+1){1'b0}}, push_ok} >= DEPTH);
  end
  assign o_full = full_q;
  assign o_level = fifo_level + {{QAW{1'b0}}, p_inflight};

  wire h_arc, h_cw, h_sxn, h_syn;
  wire [1:0] h_q;
  wire [2:0] h_k;
  wire [W-1:0] h_ci, h_co;
  wire [W:0] h_sub, h_add;
  wire [W+1:0] h_ti1, h_ti2, h_tim1, h_to2;
  wire [7:0] h_flags;
  assign {h_arc, h_cw, h_sxn, h_syn, h_q, h_k, h_ci, h_co,
          h_sub, h_add, h_ti1, h_ti2, h_tim1, h_to2, h_flags} = head;

  interp_dp #(.W(W)) u_dp (
      .i_clk(i_clk), .i_rst(i_rst | i_abort), .i_cmd(i_cmd),
      .i_valid(head_valid), .o_ready(pop),
      .i_arc(h_arc), .i_cw(h_cw), .i_sxn(h_sxn), .i_syn(h_syn), .i_q(h_q), .i_k(h_k),
      .i_ci(h_ci), .i_co(h_co), .i_sub(h_sub), .i_add(h_add),
      .i_ti1(h_ti1), .i_ti2(h_ti2), .i_tim1(h_tim1), .i_to2(h_to2), .i_flags(h_flags),
      .o_pulse(o_pulse), .o_pulse_y(o_pulse_y), .o_pulse_neg(o_pulse_neg),
      .o_pulse_last(o_pulse_last), .o_busy(o_busy),
      .o_xmag(o_xmag), .o_xneg(o_xneg), .o_ymag(o_ymag), .o_yneg(o_yneg),
      .o_d(o_d), .o_q(o_q), .o_k(o_k), .o_arc(o_arc)
  );

endmodule
