// wb_regs: the register file of interp_top, a Wishbone B4 classic slave
// (32-bit data, byte addresses of 32-bit words, whole-word writes: SEL is
// not used). Every access is acknowledged two clocks after STB (two wait
// states: the address decode, then the write or the read multiplexer, each
// ends in a register); DAT_O is valid with ACK only. A master must hold
// its signals until ACK (B4 classic) and wait for ACK, not count clocks.
// Offsets and fields come from interp_regs.vh, generated from regmap.def
// (docs/regmap.md).
`default_nettype none

module wb_regs #(
    parameter integer W = 24,   // coordinate width
    parameter integer QAW = 4,  // log2 of the queue depth
    parameter integer TW = 12   // step timing width (STEP_LEN .. DIR_HOLD bits)
) (
    input  wire          i_clk,
    input  wire          i_rst,
    // Wishbone
    input  wire          i_wb_cyc,
    input  wire          i_wb_stb,
    input  wire          i_wb_we,
    input  wire [7:0]    i_wb_adr,
    input  wire [31:0]   i_wb_dat,
    output reg  [31:0]   o_wb_dat,
    output reg           o_wb_ack,
    // Control
    output reg  [1:0]    o_src,
    output reg           o_abort,   // one clock
    output reg           o_clear,   // one clock
    output reg  [31:0]   o_feed,
    output reg  [TW-1:0] o_len,
    output reg  [TW-1:0] o_space,
    output reg  [TW-1:0] o_setup,
    output reg  [TW-1:0] o_hold,
    // Staged block and push
    output reg           o_push,    // one clock, only when the queue is not full
    output wire [4*W+8:0] o_blk,    // the staged block: [BLK_BITS-1:0], interp_block.vh
    // Status
    input  wire          i_busy,
    input  wire          i_full,
    input  wire [QAW+1:0] i_level,
    input  wire          i_overrun,
    input  wire [15:0]   i_ovr_count,
    input  wire [31:0]   i_pos_x,
    input  wire [31:0]   i_pos_y,
    input  wire [31:0]   i_moves
);

`include "interp_regs.vh"
`include "interp_block.vh"

  localparam integer QDEPTH = (1 << QAW) + 2;  // memory, its output, the datapath

  // The bus in two clocks, each ending in registers:
  //   clock 0 (STB, idle): the address is registered (adr_q), and decoded
  //     into one-hot read selects, registered too (rsel_q), in every clock
  //     whatever the access; st1_q (and wr1_q for a write) marks the access;
  //   clock 1 (st1_q): a write lands, its word decoded from adr_q (DAT_I
  //     is still held: a Wishbone B4 classic master holds its signals
  //     until ACK), the strobes are registered; DAT_O loads the word
  //     rsel_q selects;
  //   clock 2: ACK, with DAT_O.
  // So ACK comes two clocks after the strobe (two wait states), never two
  // in a row; no clock has the address decode and the read multiplexer
  // both (issue 15: the Wishbone read was top's critical path).
  reg st1_q, wr1_q;
  wire acc = i_wb_cyc & i_wb_stb & ~st1_q & ~o_wb_ack;
  wire [7:0] adr = {i_wb_adr[7:2], 2'b00};
  wire [1:0] unused_adr = i_wb_adr[1:0];
  reg [7:2] adr_q;
  wire [7:0] wadr = {adr_q, 2'b00};
  always @(posedge i_clk) begin
    if (i_rst) begin
      st1_q <= 1'b0;
      wr1_q <= 1'b0;
      o_wb_ack <= 1'b0;
    end else begin
      st1_q <= acc;
      wr1_q <= acc & i_wb_we;
      o_wb_ack <= st1_q;
    end
  end
  always @(posedge i_clk) adr_q <= adr[7:2];

  // The read selects, one a readable word, registered.
  localparam integer S_ID = 0, S_PARAMS = 1, S_CTRL = 2, S_STATUS = 3, S_OVR = 4, S_POS_X = 5,
      S_POS_Y = 6, S_MOVES = 7, NRS = 8;
  reg [NRS-1:0] rsel_q;
  always @(posedge i_clk)
    rsel_q <= {adr == A_MOVES, adr == A_POS_Y, adr == A_POS_X, adr == A_OVR_COUNT,
               adr == A_STATUS, adr == A_CTRL, adr == A_PARAMS, adr == A_ID};

  // The write enables of clock 1, one a writable word (one-hot or zero).
  localparam integer S_FEED = 0, S_LEN = 1, S_SPACE = 2, S_SETUP = 3, S_HOLD = 4, S_MODE = 5,
      S_CI = 6, S_CO = 7, S_TI = 8, S_TO = 9, S_PUSH = 10, S_WCTRL = 11, NWS = 12;
  wire [NWS-1:0] wsel = {NWS{wr1_q}} &
      {wadr == A_CTRL, wadr == A_PUSH, wadr == A_BLK_TO, wadr == A_BLK_TI,
       wadr == A_BLK_CO, wadr == A_BLK_CI, wadr == A_BLK_MODE, wadr == A_DIR_HOLD,
       wadr == A_DIR_SETUP, wadr == A_STEP_SPACE, wadr == A_STEP_LEN, wadr == A_FEED};

  reg [8:0] mode_q;
  reg [W-1:0] ci_q, co_q, ti_q, to_q;
  reg reject_q;
  // The staged block: the BLK_MODE register's fields and the magnitudes,
  // the fields the kind does not use zeroed (interp_core takes them as 0:
  // a line's CI, CO, Q, K, an arc's SXN, SYN; regmap.def says the host's
  // are ignored). The mode bits are zeroed as they are written (the
  // register is write only), the magnitudes here (a write of BLK_MODE may
  // come after theirs).
  wire arc_q = mode_q[BLK_MODE_ARC];
  assign o_blk[BLK_ARC] = arc_q;
  assign o_blk[BLK_CW] = mode_q[BLK_MODE_CW];
  assign o_blk[BLK_SXN] = mode_q[BLK_MODE_SXN];
  assign o_blk[BLK_SYN] = mode_q[BLK_MODE_SYN];
  assign o_blk[BLK_Q +: 2] = mode_q[BLK_MODE_Q +: 2];
  assign o_blk[BLK_K +: 3] = mode_q[BLK_MODE_K +: 3];
  assign o_blk[BLK_CI +: W] = arc_q ? ci_q : {W{1'b0}};
  assign o_blk[BLK_CO +: W] = arc_q ? co_q : {W{1'b0}};
  assign o_blk[BLK_TI +: W] = ti_q;
  assign o_blk[BLK_TO +: W] = to_q;

  // The BLK_MODE bits a kind uses: a line its signs, an arc its sense,
  // quadrant and crossings (the kind bit both).
  function automatic [8:0] mode_used(input arc);
    begin
      mode_used = 9'd0;
      mode_used[BLK_MODE_ARC] = 1'b1;
      mode_used[BLK_MODE_CW] = 1'b1;
      mode_used[BLK_MODE_SXN] = ~arc;
      mode_used[BLK_MODE_SYN] = ~arc;
      mode_used[BLK_MODE_Q +: 2] = {2{arc}};
      mode_used[BLK_MODE_K +: 3] = {3{arc}};
    end
  endfunction

  // Writable registers.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_src <= R_CTRL[CTRL_SRC +: 2];
      o_feed <= R_FEED;
      o_len <= R_STEP_LEN[TW-1:0];
      o_space <= R_STEP_SPACE[TW-1:0];
      o_setup <= R_DIR_SETUP[TW-1:0];
      o_hold <= R_DIR_HOLD[TW-1:0];
      mode_q <= R_BLK_MODE[8:0];
      ci_q <= R_BLK_CI[W-1:0];
      co_q <= R_BLK_CO[W-1:0];
      ti_q <= R_BLK_TI[W-1:0];
      to_q <= R_BLK_TO[W-1:0];
    end else begin
      if (wsel[S_WCTRL]) o_src <= i_wb_dat[CTRL_SRC +: 2];
      if (wsel[S_FEED]) o_feed <= i_wb_dat;
      if (wsel[S_LEN]) o_len <= i_wb_dat[TW-1:0];
      if (wsel[S_SPACE]) o_space <= i_wb_dat[TW-1:0];
      if (wsel[S_SETUP]) o_setup <= i_wb_dat[TW-1:0];
      if (wsel[S_HOLD]) o_hold <= i_wb_dat[TW-1:0];
      if (wsel[S_MODE]) mode_q <= i_wb_dat[8:0] & mode_used(i_wb_dat[BLK_MODE_ARC]);
      if (wsel[S_CI]) ci_q <= i_wb_dat[W-1:0];
      if (wsel[S_CO]) co_q <= i_wb_dat[W-1:0];
      if (wsel[S_TI]) ti_q <= i_wb_dat[W-1:0];
      if (wsel[S_TO]) to_q <= i_wb_dat[W-1:0];
    end
  end

  // Strobes: abort, clear, push.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_abort <= 1'b0;
      o_clear <= 1'b0;
      o_push <= 1'b0;
    end else begin
      o_abort <= wsel[S_WCTRL] & i_wb_dat[CTRL_ABORT];
      o_clear <= wsel[S_WCTRL] & i_wb_dat[CTRL_CLEAR];
      o_push <= wsel[S_PUSH] & ~i_full;
    end
  end

  // Sticky reject: a push to a full queue.
  always @(posedge i_clk) begin
    if (i_rst || o_clear) reject_q <= 1'b0;
    else if (wsel[S_PUSH] & i_full) reject_q <= 1'b1;
  end

  // Read data: the word rsel_q selects (all zero: a write-only or unused
  // word reads 0), an AND-OR of the sources, loaded in every clock (the
  // master reads DAT_O only with ACK). The configuration (FEED, the step
  // timing) and the staged block are write only (regmap.def).
  wire [31:0] params = {16'd0, QDEPTH[7:0], W[7:0]};
  wire [31:0] status;
  assign status[STATUS_BUSY] = i_busy;
  assign status[STATUS_EMPTY] = (i_level == 0);
  assign status[STATUS_FULL] = i_full;
  assign status[STATUS_OVERRUN] = i_overrun;
  assign status[STATUS_REJECT] = reject_q;
  assign status[7:5] = 3'd0;
  assign status[STATUS_LEVEL +: 8] = {{(6-QAW){1'b0}}, i_level};
  assign status[31:16] = 16'd0;
  wire [31:0] rdata = ({32{rsel_q[S_ID]}} & R_ID) | ({32{rsel_q[S_PARAMS]}} & params) |
                      ({32{rsel_q[S_CTRL]}} & {30'd0, o_src}) | ({32{rsel_q[S_STATUS]}} & status) |
                      ({32{rsel_q[S_OVR]}} & {16'd0, i_ovr_count}) | ({32{rsel_q[S_POS_X]}} & i_pos_x) |
                      ({32{rsel_q[S_POS_Y]}} & i_pos_y) | ({32{rsel_q[S_MOVES]}} & i_moves);
  always @(posedge i_clk) o_wb_dat <= rdata;

`ifdef FORMAL
  // ------------------------------------------------------------- formal
  // Proved unbounded by rtl/interp/formal/prove_regs.sh (ctest
  // interp_regs_formal, ABC's PDR) for any master that keeps to Wishbone
  // B4 classic: once an access has started it holds CYC, STB, WE, the
  // address and the data until ACK (it may drop or change them in the
  // ACK clock). f_out_q: the master's access is outstanding (started, no
  // ACK yet); f_start: an access starts in this clock.
  reg f_past, f_past2, f_out_q;
  initial f_past = 1'b0;
  initial f_past2 = 1'b0;
  always @(posedge i_clk) begin
    f_past <= 1'b1;
    f_past2 <= f_past;
  end
  always @(*) if (!f_past) assume (i_rst);
  always @(posedge i_clk) begin
    if (i_rst | o_wb_ack) f_out_q <= 1'b0;
    else if (i_wb_cyc & i_wb_stb) f_out_q <= 1'b1;
  end
  wire f_start = i_wb_cyc & i_wb_stb & ~f_out_q & ~i_rst;
  reg f_we_q;
  reg [7:0] f_adr_q;
  reg [31:0] f_dat_q;
  always @(posedge i_clk) begin
    f_we_q <= i_wb_we;
    f_adr_q <= i_wb_adr;
    f_dat_q <= i_wb_dat;
  end
  always @(*)
    if (f_past && f_out_q && !o_wb_ack)
      assume (i_wb_cyc && i_wb_stb && i_wb_we == f_we_q && i_wb_adr == f_adr_q && i_wb_dat == f_dat_q);
  // What the read of the address on the bus returns, from the inputs of
  // this clock (a case on the address, not the one-hot selects).
  reg [31:0] f_word;
  always @(*) begin
    f_word = 32'd0;
    case (adr)
      A_ID: f_word = R_ID;
      A_PARAMS: f_word = {16'd0, QDEPTH[7:0], W[7:0]};
      A_CTRL: f_word[CTRL_SRC +: 2] = o_src;
      A_STATUS: begin
        f_word[STATUS_BUSY] = i_busy;
        f_word[STATUS_EMPTY] = (i_level == 0);
        f_word[STATUS_FULL] = i_full;
        f_word[STATUS_OVERRUN] = i_overrun;
        f_word[STATUS_REJECT] = reject_q;
        f_word[STATUS_LEVEL +: QAW+2] = i_level;
      end
      A_OVR_COUNT: f_word[15:0] = i_ovr_count;
      A_POS_X: f_word = i_pos_x;
      A_POS_Y: f_word = i_pos_y;
      A_MOVES: f_word = i_moves;
      default: ;
    endcase
  end
  wire f_wr_push = f_start & i_wb_we & (adr == A_PUSH);
  always @(posedge i_clk) begin
    if (f_past && !$past(i_rst)) begin
      // ACK two clocks after the access starts, and only then: one ACK
      // an access, never two in a row.
      assert (o_wb_ack == (f_past2 && !$past(i_rst, 2) && $past(f_start, 2)));
      if (o_wb_ack) assert (!$past(o_wb_ack));
      // A read returns the addressed word as it was in the clock before ACK.
      if (o_wb_ack && !$past(i_wb_we, 2)) assert (o_wb_dat == $past(f_word));
      // A write lands once, in the clock after the access starts: the
      // word holds the access's data from the ACK on, and changes only so.
      if (o_feed != $past(o_feed))
        assert (f_past2 && $past(f_start & i_wb_we & (adr == A_FEED), 2));
      if (f_past2 && !$past(i_rst, 2) && $past(f_start & i_wb_we & (adr == A_FEED), 2))
        assert (o_feed == $past(i_wb_dat, 2));
      if (ci_q != $past(ci_q)) assert (f_past2 && $past(f_start & i_wb_we & (adr == A_BLK_CI), 2));
      if (o_src != $past(o_src)) assert (f_past2 && $past(f_start & i_wb_we & (adr == A_CTRL), 2));
      // A PUSH write pushes once, unless the queue is full in the clock
      // after it starts (then REJECT is set instead).
      assert (o_push == (f_past2 && !$past(i_rst, 2) && $past(f_wr_push, 2) && !$past(i_full)));
      if (f_past2 && !$past(i_rst, 2) && $past(f_wr_push, 2) && $past(i_full)) assert (reject_q);
      // The staged block has a line's CI, CO, Q, K and an arc's SXN, SYN
      // zero, whatever the host wrote.
      if (!o_blk[BLK_ARC]) assert (o_blk[BLK_CI +: W] == 0 && o_blk[BLK_CO +: W] == 0 &&
                                   o_blk[BLK_Q +: 2] == 0 && o_blk[BLK_K +: 3] == 0);
      if (o_blk[BLK_ARC]) assert (!o_blk[BLK_SXN] && !o_blk[BLK_SYN]);
      // ABORT and CLEAR only from a CTRL write.
      if (o_abort | o_clear) assert (f_past2 && $past(f_start & i_wb_we & (adr == A_CTRL), 2));
    end
  end
`endif

endmodule
