// wb_regs: the register file of interp_top, a Wishbone B4 classic slave
// (32-bit data, byte addresses of 32-bit words, whole-word writes: SEL is
// not used). Every access is acknowledged in the clock after STB (one
// wait state); reads are registered (DAT_O is valid with ACK only).
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

  wire acc = i_wb_cyc & i_wb_stb & ~o_wb_ack;
  wire wr = acc & i_wb_we;
  wire [7:0] adr = {i_wb_adr[7:2], 2'b00};
  wire [1:0] unused_adr = i_wb_adr[1:0];

  reg [8:0] mode_q;
  reg [W-1:0] xs_q, ys_q, xe_q, ye_q;
  reg reject_q;
  // The staged block: the BLK_MODE register's fields and the magnitudes.
  assign o_blk[BLK_ARC] = mode_q[BLK_MODE_ARC];
  assign o_blk[BLK_CW] = mode_q[BLK_MODE_CW];
  assign o_blk[BLK_SXN] = mode_q[BLK_MODE_SXN];
  assign o_blk[BLK_SYN] = mode_q[BLK_MODE_SYN];
  assign o_blk[BLK_Q +: 2] = mode_q[BLK_MODE_Q +: 2];
  assign o_blk[BLK_K +: 3] = mode_q[BLK_MODE_K +: 3];
  assign o_blk[BLK_XS +: W] = xs_q;
  assign o_blk[BLK_YS +: W] = ys_q;
  assign o_blk[BLK_XE +: W] = xe_q;
  assign o_blk[BLK_YE +: W] = ye_q;

  // Acknowledge: one clock after the strobe, never two in a row.
  always @(posedge i_clk) begin
    if (i_rst) o_wb_ack <= 1'b0;
    else o_wb_ack <= acc;
  end

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
      xs_q <= R_BLK_XS[W-1:0];
      ys_q <= R_BLK_YS[W-1:0];
      xe_q <= R_BLK_XE[W-1:0];
      ye_q <= R_BLK_YE[W-1:0];
    end else if (wr) begin
      case (adr)
        A_CTRL: o_src <= i_wb_dat[CTRL_SRC +: 2];
        A_FEED: o_feed <= i_wb_dat;
        A_STEP_LEN: o_len <= i_wb_dat[TW-1:0];
        A_STEP_SPACE: o_space <= i_wb_dat[TW-1:0];
        A_DIR_SETUP: o_setup <= i_wb_dat[TW-1:0];
        A_DIR_HOLD: o_hold <= i_wb_dat[TW-1:0];
        A_BLK_MODE: mode_q <= i_wb_dat[8:0];
        A_BLK_XS: xs_q <= i_wb_dat[W-1:0];
        A_BLK_YS: ys_q <= i_wb_dat[W-1:0];
        A_BLK_XE: xe_q <= i_wb_dat[W-1:0];
        A_BLK_YE: ye_q <= i_wb_dat[W-1:0];
        default: ;
      endcase
    end
  end

  // Strobes: abort, clear, push.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_abort <= 1'b0;
      o_clear <= 1'b0;
      o_push <= 1'b0;
    end else begin
      o_abort <= wr && adr == A_CTRL && i_wb_dat[CTRL_ABORT];
      o_clear <= wr && adr == A_CTRL && i_wb_dat[CTRL_CLEAR];
      o_push <= wr && adr == A_PUSH && !i_full;
    end
  end

  // Sticky reject: a push to a full queue.
  always @(posedge i_clk) begin
    if (i_rst || o_clear) reject_q <= 1'b0;
    else if (wr && adr == A_PUSH && i_full) reject_q <= 1'b1;
  end

  // Read data. The configuration (FEED, the step timing) and the staged
  // block are write only (regmap.def): only status, counters and CTRL.SRC
  // reach the read multiplexer. The register loads the addressed word in
  // every clock, whatever the access (Wishbone reads DAT_O only with ACK,
  // the clock after the strobe): no enable and no clear from the strobe
  // and the write enable, which made the address decode deeper (issue 15).
  reg [31:0] rdata;
  always @(*) begin
    rdata = 32'd0;
    case (adr)
      A_ID: rdata = R_ID;
      A_PARAMS: begin
        rdata[PARAMS_W +: 8] = W[7:0];
        rdata[PARAMS_QDEPTH +: 8] = QDEPTH[7:0];
      end
      A_CTRL: rdata[CTRL_SRC +: 2] = o_src;
      A_STATUS: begin
        rdata[STATUS_BUSY] = i_busy;
        rdata[STATUS_EMPTY] = (i_level == 0);
        rdata[STATUS_FULL] = i_full;
        rdata[STATUS_OVERRUN] = i_overrun;
        rdata[STATUS_REJECT] = reject_q;
        rdata[STATUS_LEVEL +: QAW+2] = i_level;
      end
      A_OVR_COUNT: rdata[15:0] = i_ovr_count;
      A_POS_X: rdata = i_pos_x;
      A_POS_Y: rdata = i_pos_y;
      A_MOVES: rdata = i_moves;
      default: ;
    endcase
  end
  always @(posedge i_clk) o_wb_dat <= rdata;

endmodule
