// link_ctrl: the frame engine of the host link (docs/board.md, "Protocol").
// Takes each frame link_rx reports, checks it whole before anything is
// written, carries out its ops as a Wishbone master and queues the reply's
// bytes for link_tx:
//
//   1. length and CRC (ERR_LEN, ERR_CRC);
//   2. a scan of the ops: each names a known register, readable or
//      writable as the op asks (ERR_REG), and a write has its 4 bytes
//      (ERR_LEN); the error's detail is the op's byte index;
//   3. sequence: a frame with writes must carry the expected sequence
//      number (ERR_SEQ), or the previous one (ERR_DUP: done already, its
//      reply was lost); a frame of reads only is done with any number;
//   4. the ops in order, the reads' data into the reply;
//   5. the trailer, laid out by board.def's REPLY lines (REPLY_* of
//      board_proto.vh): the two queue levels and the flags, read from the
//      peripherals' STATUS registers over the bus; the positions of the
//      axes the STEP/DIR pins show (X and Y of interp3_top, or of
//      interp_top when i_pins; Z of interp3_top), each read over the bus
//      when its bytes are due; the next expected sequence number.
// Reply: seq, status, (detail if refused), read data, trailer. A refused
// frame writes nothing. Bus: word addresses (7 bits), classic cycles.
`default_nettype none

module link_ctrl #(
    parameter integer MAX = 64  // frame buffer bank size (link_rx)
) (
    input  wire        i_clk,
    input  wire        i_rst,
    // The frame from link_rx
    input  wire        i_done,
    input  wire        i_bank,
    input  wire [7:0]  i_len,
    input  wire        i_crc_ok,
    input  wire        i_bad,
    output wire        o_busy,
    output wire [7:0]  o_rd_addr,
    input  wire [7:0]  i_rd_data,
    // Wishbone master
    output reg         o_wb_cyc,
    output reg         o_wb_we,
    output reg  [6:0]  o_wb_adr,
    output reg  [31:0] o_wb_dat,
    input  wire [31:0] i_wb_dat,
    input  wire        i_wb_ack,
    // Reply bytes to link_tx: {last, byte}
    output reg  [8:0]  o_tx_data,
    output reg         o_tx_push,
    input  wire        i_tx_full,
    // Link state for the flags
    input  wire        i_hold,
    input  wire        i_stopped,
    input  wire        i_wdog,
    input  wire        i_pins,     // LINK CTRL.PINS: X and Y pins from interp_top
    // One clock at each frame done (OK) / refused
    output reg         o_frame_ok,
    output reg         o_refused
);

`include "board_proto.vh"

  localparam [3:0] S_IDLE = 4'd0, S_FETCH = 4'd1, S_SEQ = 4'd2, S_SCAN = 4'd3, S_HEAD = 4'd4,
                   S_OP = 4'd5, S_WDAT = 4'd6, S_BUS = 4'd7, S_RDAT = 4'd8, S_TRAIL_BUS = 4'd9,
                   S_TRAIL = 4'd10, S_TRAIL_POS = 4'd11;

  reg [3:0] state_q, ret_q;
  reg bank_q;
  reg [7:0] len_q;   // frame length
  reg [7:0] idx_q;   // byte index being read
  reg [7:0] seq_q;
  reg [7:0] exp_q;   // the expected sequence number of a frame with writes
  reg [2:0] err_q;
  reg [7:0] det_q;   // error detail: the op's byte index
  reg has_wr_q;
  reg [6:0] op_q;    // the write op's word address
  reg [4:0] k_q;     // byte counter in a word, trailer byte counter
  reg [31:0] data_q; // write data collected / read data to send
  reg [1:0] hb_q;    // header byte counter
  reg [7:0] lvl3_q, lvl2_q;
  reg rej_q;
  reg trail_rd_q;    // which STATUS the trailer reads: 0 AXIS3, 1 INTERP
  reg pos_rd_q;      // the position of the field at k_q is in data_q

  wire [7:0] end_idx = len_q - 8'd2;  // the first CRC byte
  wire [6:0] op_adr = i_rd_data[6:0];
  wire op_wr = i_rd_data[7];

  assign o_busy = (state_q != S_IDLE);
  assign o_rd_addr = (bank_q ? MAX[7:0] : 8'd0) + idx_q;  // bank * MAX + index

  // The trailer's fields by byte index k_q (board.def's REPLY lines; a
  // position's bytes are the top bytes of its 32-bit register, the other
  // fields are 1 byte).
  localparam [4:0] T_LAST = REPLY_TRAILER[4:0] - 5'd1;
  localparam [4:0] T_PX = REPLY_POS_X[4:0], T_PY = REPLY_POS_Y[4:0], T_PZ = REPLY_POS_Z[4:0];
  localparam [4:0] N_PX = REPLY_POS_X_BYTES[4:0], N_PY = REPLY_POS_Y_BYTES[4:0], N_PZ = REPLY_POS_Z_BYTES[4:0];
  wire pos_start = k_q == T_PX || k_q == T_PY || k_q == T_PZ;
  wire in_pos = (k_q >= T_PX && k_q < T_PX + N_PX) || (k_q >= T_PY && k_q < T_PY + N_PY) ||
                (k_q >= T_PZ && k_q < T_PZ + N_PZ);
  wire [6:0] pos_adr = k_q == T_PX ? (i_pins ? W_INTERP_POS_X : W_AXIS3_POS_X) :
                       k_q == T_PY ? (i_pins ? W_INTERP_POS_Y : W_AXIS3_POS_Y) : W_AXIS3_POS_Z;

  // Reply byte of the header and the trailer.
  reg [7:0] head_byte, trail_byte;
  always @(*) begin
    case (hb_q)
      2'd0: head_byte = seq_q;
      2'd1: head_byte = {5'd0, err_q};
      default: head_byte = det_q;
    endcase
    if (in_pos) trail_byte = data_q[31:24];
    else if (k_q == REPLY_LEVEL3[4:0]) trail_byte = lvl3_q;
    else if (k_q == REPLY_LEVEL2[4:0]) trail_byte = lvl2_q;
    else if (k_q == REPLY_FLAGS[4:0]) trail_byte = {4'd0, i_wdog, i_stopped, i_hold, rej_q};
    else if (k_q == REPLY_NEXT_SEQ[4:0]) trail_byte = exp_q;
    else trail_byte = 8'd0;
  end

  // The frame engine.
  always @(posedge i_clk) begin
    o_tx_push <= 1'b0;
    o_frame_ok <= 1'b0;
    o_refused <= 1'b0;
    if (i_rst) begin
      state_q <= S_IDLE;
      ret_q <= S_IDLE;
      bank_q <= 1'b0;
      len_q <= 8'd0;
      idx_q <= 8'd0;
      seq_q <= 8'd0;
      exp_q <= 8'd0;
      err_q <= 3'd0;
      det_q <= 8'd0;
      has_wr_q <= 1'b0;
      op_q <= 7'd0;
      k_q <= 5'd0;
      data_q <= 32'd0;
      hb_q <= 2'd0;
      lvl3_q <= 8'd0;
      lvl2_q <= 8'd0;
      rej_q <= 1'b0;
      trail_rd_q <= 1'b0;
      pos_rd_q <= 1'b0;
      o_wb_cyc <= 1'b0;
      o_wb_we <= 1'b0;
      o_wb_adr <= 7'd0;
      o_wb_dat <= 32'd0;
      o_tx_data <= 9'd0;
    end else begin
      case (state_q)
        S_IDLE: if (i_done) begin
          bank_q <= i_bank;
          len_q <= i_len;
          err_q <= ERR_OK[2:0];
          det_q <= 8'd0;
          has_wr_q <= 1'b0;
          rej_q <= 1'b0;
          hb_q <= 2'd0;
          if (i_len < 8'd3 || i_len > MAX[7:0]) err_q <= ERR_LEN[2:0];
          else if (i_bad || !i_crc_ok) err_q <= ERR_CRC[2:0];
          idx_q <= 8'd0;
          ret_q <= S_SEQ;
          state_q <= S_FETCH;
        end
        S_FETCH: state_q <= ret_q;  // the buffer's read data comes one clock later
        S_SEQ: begin
          seq_q <= i_rd_data;
          idx_q <= 8'd1;
          ret_q <= S_SCAN;
          state_q <= (err_q != ERR_OK[2:0] || end_idx == 8'd1) ? S_HEAD : S_FETCH;
        end
        // Scan: every op valid, before anything is done.
        S_SCAN: begin
          if (op_wr && idx_q + 8'd4 >= end_idx) begin
            err_q <= ERR_LEN[2:0];
            det_q <= idx_q;
            state_q <= S_HEAD;
          end else if (op_wr ? !KNOWN_WR[op_adr] : !KNOWN_RD[op_adr]) begin
            err_q <= ERR_REG[2:0];
            det_q <= idx_q;
            state_q <= S_HEAD;
          end else begin
            if (op_wr) has_wr_q <= 1'b1;
            idx_q <= idx_q + (op_wr ? 8'd5 : 8'd1);
            state_q <= (idx_q + (op_wr ? 8'd5 : 8'd1) >= end_idx) ? S_HEAD : S_FETCH;
          end
        end
        // Header: the sequence decision (once), then seq, status, detail.
        S_HEAD: if (!i_tx_full) begin
          o_tx_data <= {1'b0, head_byte};
          o_tx_push <= 1'b1;
          hb_q <= hb_q + 2'd1;
          if (hb_q == 2'd0) begin
            // The sequence decision, for a frame with writes that passed the checks.
            if (err_q == ERR_OK[2:0] && has_wr_q) begin
              if (seq_q == exp_q) exp_q <= exp_q + 8'd1;
              else begin
                err_q <= (seq_q == exp_q - 8'd1) ? ERR_DUP[2:0] : ERR_SEQ[2:0];
                det_q <= exp_q;
              end
            end
          end else if (hb_q == 2'd1) begin
            if (err_q == ERR_OK[2:0]) begin
              o_frame_ok <= 1'b1;
              idx_q <= 8'd1;
              ret_q <= S_OP;
              state_q <= (end_idx == 8'd1) ? S_TRAIL_BUS : S_FETCH;
            end
          end else begin
            state_q <= S_TRAIL_BUS;
            if (err_q == ERR_DUP[2:0]) o_frame_ok <= 1'b1;
            else o_refused <= 1'b1;
          end
        end
        // Execute: each op in order.
        S_OP: begin
          op_q <= i_rd_data[6:0];
          k_q <= 5'd0;
          if (op_wr) begin
            idx_q <= idx_q + 8'd1;
            ret_q <= S_WDAT;
            state_q <= S_FETCH;
          end else begin
            o_wb_cyc <= 1'b1;
            o_wb_we <= 1'b0;
            o_wb_adr <= op_adr;
            state_q <= S_BUS;
          end
        end
        S_WDAT: begin
          data_q <= {data_q[23:0], i_rd_data};
          k_q <= k_q + 5'd1;
          if (k_q == 5'd3) begin
            o_wb_cyc <= 1'b1;
            o_wb_we <= 1'b1;
            o_wb_adr <= op_q;
            o_wb_dat <= {data_q[23:0], i_rd_data};
            state_q <= S_BUS;
          end else begin
            idx_q <= idx_q + 8'd1;
            ret_q <= S_WDAT;
            state_q <= S_FETCH;
          end
        end
        S_BUS: if (i_wb_ack) begin
          o_wb_cyc <= 1'b0;
          data_q <= i_wb_dat;
          k_q <= 5'd0;
          if (!o_wb_we) state_q <= S_RDAT;
          else begin
            idx_q <= idx_q + 8'd1;
            ret_q <= S_OP;
            state_q <= (idx_q + 8'd1 >= end_idx) ? S_TRAIL_BUS : S_FETCH;
          end
        end
        S_RDAT: if (!i_tx_full) begin
          o_tx_data <= {1'b0, data_q[31:24]};
          o_tx_push <= 1'b1;
          data_q <= {data_q[23:0], 8'd0};
          k_q <= k_q + 5'd1;
          if (k_q == 5'd3) begin
            idx_q <= idx_q + 8'd1;
            ret_q <= S_OP;
            state_q <= (idx_q + 8'd1 >= end_idx) ? S_TRAIL_BUS : S_FETCH;
          end
        end
        // Trailer: AXIS3 STATUS, then INTERP STATUS, over the bus.
        S_TRAIL_BUS: begin
          if (!o_wb_cyc) begin
            o_wb_cyc <= 1'b1;
            o_wb_we <= 1'b0;
            o_wb_adr <= trail_rd_q ? W_INTERP_STATUS : W_AXIS3_STATUS;
          end else if (i_wb_ack) begin
            o_wb_cyc <= 1'b0;
            // REJECT: AXIS3 STATUS bit 3, INTERP STATUS bit 4; LEVEL: bits 15:8 of both.
            if (!trail_rd_q) begin
              lvl3_q <= i_wb_dat[15:8];
              rej_q <= i_wb_dat[AXIS3_STATUS_REJECT];
            end else begin
              lvl2_q <= i_wb_dat[15:8];
              rej_q <= rej_q | i_wb_dat[4];
            end
            trail_rd_q <= ~trail_rd_q;
            k_q <= 5'd0;
            pos_rd_q <= 1'b0;
            if (trail_rd_q) state_q <= S_TRAIL;
          end
        end
        // The trailer's bytes; a position is read over the bus at its first byte.
        S_TRAIL: if (pos_start && !pos_rd_q) begin
          o_wb_cyc <= 1'b1;
          o_wb_we <= 1'b0;
          o_wb_adr <= pos_adr;
          state_q <= S_TRAIL_POS;
        end else if (!i_tx_full) begin
          o_tx_data <= {k_q == T_LAST, trail_byte};
          o_tx_push <= 1'b1;
          if (in_pos) data_q <= {data_q[23:0], 8'd0};
          pos_rd_q <= 1'b0;
          k_q <= k_q + 5'd1;
          if (k_q == T_LAST) state_q <= S_IDLE;
        end
        S_TRAIL_POS: if (i_wb_ack) begin
          o_wb_cyc <= 1'b0;
          data_q <= i_wb_dat;
          pos_rd_q <= 1'b1;
          state_q <= S_TRAIL;
        end
        default: state_q <= S_IDLE;
      endcase
    end
  end

endmodule
