// interp3_top: paper B's stage 2 as a Wishbone peripheral (window AXIS3 of
// the board, register map axis3.def, docs/board-regs.md): a chord queue,
// a chord sequencer on a fixed control cycle, the 3-axis core interp3_core,
// a step/dir output stage and position counters.
//
//   regs -> move_fifo (chords) -> sequencer (cycle, DDA) -> interp3_core
//        -> step output (STEP_LEN, STEP_SPACE) -> pins;  pos_counter x3
//
// The sequencer: a cycle counter of CYCLE time-scaled clocks (i_ce, from
// board_ctl) makes a boundary every cycle while CTRL.RUN. At each boundary
// the next chord is due; it is loaded as soon as the previous one has
// given all its pulses (at once, unless the output stage made it late;
// the grid does not drift). A chord of N = |X| + |Y| + |Z| steps is spread
// by a DDA over the cycle: its command j (1..N) comes at the
// ceil(j * CYCLE / N) - 1'th time-scaled clock after the load, as paper B's
// stage 2 spreads pulse j at j * T / N (docs/algorithm.md). A command that
// the output stage cannot take yet is owed, never dropped. A boundary with
// the queue empty counts an underrun, or ends the run if CTRL.DRAIN.
//
// Synchronous, active-high reset for every flop.
`default_nettype none

module interp3_top #(
    parameter integer W = 24,   // chord magnitude width (2..30): |X| < 2^W
    parameter integer QAW = 5   // log2 of the chord queue depth
) (
    input  wire        i_clk,
    input  wire        i_rst,
    input  wire        i_ce,      // time-scaled clock enable (1: full speed)
    // Wishbone B4 classic slave
    input  wire        i_wb_cyc,
    input  wire        i_wb_stb,
    input  wire        i_wb_we,
    input  wire [7:0]  i_wb_adr,
    input  wire [31:0] i_wb_dat,
    output reg  [31:0] o_wb_dat,
    output reg         o_wb_ack,
    // Step/dir outputs
    output wire        o_step_x,
    output wire        o_dir_x,
    output wire        o_step_y,
    output wire        o_dir_y,
    output wire        o_step_z,
    output wire        o_dir_z,
    output wire        o_busy     // a chord is loaded and not finished
);

`include "board_proto.vh"

  localparam integer QDEPTH = (1 << QAW) + 1;  // the memory and its output register
  localparam [7:0] QDEPTH8 = QDEPTH[7:0];
  localparam integer QW = 3 * (W + 1);
  localparam integer DW = (W + 2 > 16 ? W + 2 : 16) + 1;  // DDA: N + an accumulator below CYCLE  // a queued chord: {zneg, |Z|, yneg, |Y|, xneg, |X|}

  // ------------------------------------------------------------ registers
  wire acc = i_wb_cyc & i_wb_stb & ~o_wb_ack;
  wire wr = acc & i_wb_we;
  wire [7:0] adr = {i_wb_adr[7:2], 2'b00};
  wire [1:0] unused_adr = i_wb_adr[1:0];

  reg run_q, drain_q, reject_q, underrun_q;
  reg [15:0] cycle_q;
  reg [W:0] chx_q, chy_q, chz_q;  // staged chord: sign and W bits of two's complement
  reg [31:0] chords_q, underruns_q;
  reg [15:0] len_q, space_q;
  wire q_full, q_valid;
  wire [QW-1:0] q_data;
  wire [QAW+1:0] q_level;
  wire [QAW:0] q_used;  // chords in the queue's memory (head excluded)
  assign q_full = q_used[QAW];  // move_fifo takes no push when full: refused above
  wire [31:0] pos_x, pos_y, pos_z;

  // Acknowledge.
  always @(posedge i_clk) begin
    if (i_rst) o_wb_ack <= 1'b0;
    else o_wb_ack <= acc;
  end

  wire wr_ctrl = wr && adr == A_AXIS3_CTRL;
  wire abort = wr_ctrl && i_wb_dat[AXIS3_CTRL_ABORT];
  wire clear = wr_ctrl && i_wb_dat[AXIS3_CTRL_CLEAR];
  wire push_req = wr && (adr == A_AXIS3_PUSH || adr == A_AXIS3_CHORD);
  wire push = push_req && !q_full;

  // A chord as sign and magnitude: a 32-bit two's complement word.
  // The host keeps |v| < 2^W (bits above W-1 of the magnitude are dropped).
  // The low W bits of -v are those of ~v + 1.
  function automatic [W:0] sm(input neg, input [W-1:0] lo);
    sm = {neg, neg ? (~lo + {{(W-1){1'b0}}, 1'b1}) : lo};
  endfunction
  // A 10-bit field of CHORD, sign-extended.
  function automatic [31:0] sx10(input [9:0] f);
    sx10 = {{22{f[9]}}, f};
  endfunction

  wire [31:0] cx = sx10(i_wb_dat[AXIS3_CHORD_CX +: 10]);
  wire [31:0] cy = sx10(i_wb_dat[AXIS3_CHORD_CY +: 10]);
  wire [31:0] cz = sx10(i_wb_dat[AXIS3_CHORD_CZ +: 10]);
  wire unused_c = ^{cx[30:W], cy[30:W], cz[30:W]};
  wire [QW-1:0] q_in = (adr == A_AXIS3_CHORD)
      ? {sm(cz[31], cz[W-1:0]), sm(cy[31], cy[W-1:0]), sm(cx[31], cx[W-1:0])}
      : {sm(chz_q[W], chz_q[W-1:0]), sm(chy_q[W], chy_q[W-1:0]), sm(chx_q[W], chx_q[W-1:0])};

  // Writable registers.
  always @(posedge i_clk) begin
    if (i_rst) begin
      cycle_q <= R_AXIS3_CYCLE[15:0];
      len_q <= R_AXIS3_STEP_LEN[15:0];
      space_q <= R_AXIS3_STEP_SPACE[15:0];
      chx_q <= {(W+1){1'b0}};
      chy_q <= {(W+1){1'b0}};
      chz_q <= {(W+1){1'b0}};
    end else if (wr) begin
      case (adr)
        A_AXIS3_CYCLE: cycle_q <= (i_wb_dat[15:0] == 16'd0) ? 16'd1 : i_wb_dat[15:0];
        A_AXIS3_STEP_LEN: len_q <= i_wb_dat[15:0];
        A_AXIS3_STEP_SPACE: space_q <= i_wb_dat[15:0];
        A_AXIS3_CH_X: chx_q <= {i_wb_dat[31], i_wb_dat[W-1:0]};
        A_AXIS3_CH_Y: chy_q <= {i_wb_dat[31], i_wb_dat[W-1:0]};
        A_AXIS3_CH_Z: chz_q <= {i_wb_dat[31], i_wb_dat[W-1:0]};
        default: ;
      endcase
    end
  end

  // Sticky flags.
  always @(posedge i_clk) begin
    if (i_rst || clear) reject_q <= 1'b0;
    else if (push_req && q_full) reject_q <= 1'b1;
  end

  // ------------------------------------------------------------ sequencer
  reg [15:0] cyc_q;       // time-scaled clocks into the cycle
  reg due_q;              // the chord of the last boundary is not loaded yet
  reg loaded_q;           // a chord is in the core
  reg [DW-1:0] dda_q;     // DDA accumulator of the cycle's chord, < CYCLE
  reg [W+1:0] rem_q;      // DDA commands still to come in this cycle
  reg [W+1:0] n_q;        // the cycle's chord's N
  reg [15:0] owed_q;      // commands due to the loaded chord, not yet given
  reg [15:0] nxt_q;       // commands due to the chord not yet loaded
  reg cmd_q;              // a command went to the core in the last clock
  reg [1:0] out_q;        // output phase: 0 idle, 1 step high, 2 space
  reg [15:0] ocnt_q;
  reg [2:0] stp_q;        // the step pins
  wire core_done, sx, sy, sz;
  wire strobe = sx | sy | sz;

  wire [W+1:0] n_head = {2'b00, q_data[W-1:0]} + {2'b00, q_data[2*W:W+1]} + {2'b00, q_data[3*W+1:2*W+2]};
  // A boundary: the grid's first time-scaled clock of a cycle, unless the
  // last boundary's chord is still not loaded (then the cycle stretches).
  wire boundary = i_ce && run_q && cyc_q == 16'd0 && !due_q;
  wire out_idle = out_q == 2'd0 && !strobe && !cmd_q;
  wire finished = core_done && owed_q == 16'd0 && out_idle;
  wire pop = due_q && finished;            // load the due chord
  // The DDA: the boundary restarts it with the head's N (command j of N at
  // the ceil(j * CYCLE / N) - 1'th time-scaled clock from the boundary).
  wire [W+1:0] n_now = boundary ? n_head : n_q;
  wire [DW-1:0] dda_sum = (boundary ? {DW{1'b0}} : dda_q) + {{(DW-W-2){1'b0}}, n_now};
  wire [DW-1:0] cycle_w = {{(DW-16){1'b0}}, cycle_q};
  wire dda_on = boundary ? q_valid : (i_ce && rem_q != 0);
  wire tick = dda_on && dda_sum >= cycle_w;
  wire to_next = boundary || due_q;        // the tick belongs to the chord not yet loaded
  wire core_ready;  // interp3_core has prepared the loaded chord (4 clocks after the load)
  wire cmd = loaded_q && !pop && owed_q != 16'd0 && out_idle && core_ready;

  move_fifo #(.WIDTH(QW), .AW(QAW)) u_queue (
      .i_clk(i_clk), .i_rst(i_rst), .i_flush(abort), .i_push(push), .i_data(q_in),
      .i_pop(pop), .o_valid(q_valid), .o_data(q_data), .o_level(q_level), .o_used(q_used)
  );

  // Cycle counter.
  always @(posedge i_clk) begin
    if (i_rst || abort) cyc_q <= 16'd0;
    else if (i_ce && (cyc_q != 16'd0 || boundary))
      cyc_q <= ({1'b0, cyc_q} + 17'd1 >= {1'b0, cycle_q}) ? 16'd0 : cyc_q + 16'd1;
  end

  // RUN and DRAIN; underruns: decided at each boundary.
  always @(posedge i_clk) begin
    if (i_rst || abort) begin
      run_q <= 1'b0;
      drain_q <= 1'b0;
    end else if (wr_ctrl) begin
      run_q <= i_wb_dat[AXIS3_CTRL_RUN];
      drain_q <= i_wb_dat[AXIS3_CTRL_DRAIN];
    end else if (boundary && !q_valid && drain_q) begin
      run_q <= 1'b0;
      drain_q <= 1'b0;
    end
  end
  always @(posedge i_clk) begin
    if (i_rst || clear) begin
      underrun_q <= 1'b0;
      underruns_q <= 32'd0;
    end else if (boundary && !q_valid && !drain_q) begin
      underrun_q <= 1'b1;
      underruns_q <= underruns_q + 32'd1;
    end
  end

  // Chords loaded into the core.
  always @(posedge i_clk) begin
    if (i_rst) chords_q <= 32'd0;
    else if (pop) chords_q <= chords_q + 32'd1;
  end

  // The DDA of the cycle's chord.
  always @(posedge i_clk) begin
    if (i_rst || abort) begin
      dda_q <= {DW{1'b0}};
      rem_q <= {(W+2){1'b0}};
      n_q <= {(W+2){1'b0}};
    end else if (boundary) begin
      n_q <= q_valid ? n_head : {(W+2){1'b0}};
      rem_q <= q_valid ? n_head - {{(W+1){1'b0}}, tick} : {(W+2){1'b0}};
      dda_q <= q_valid ? (tick ? dda_sum - cycle_w : dda_sum) : {DW{1'b0}};
    end else if (dda_on) begin
      dda_q <= tick ? dda_sum - cycle_w : dda_sum;
      rem_q <= rem_q - {{(W+1){1'b0}}, tick};
    end
  end

  // The due flag, the loaded flag and the commands owed.
  always @(posedge i_clk) begin
    if (i_rst || abort) begin
      due_q <= 1'b0;
      loaded_q <= 1'b0;
      owed_q <= 16'd0;
      nxt_q <= 16'd0;
    end else if (pop) begin
      due_q <= 1'b0;
      loaded_q <= 1'b1;
      owed_q <= nxt_q + {15'd0, tick};
      nxt_q <= 16'd0;
    end else begin
      if (boundary) due_q <= q_valid;
      nxt_q <= nxt_q + {15'd0, tick & to_next};
      owed_q <= owed_q + {15'd0, tick & ~to_next} - {15'd0, cmd};
      if (finished && !boundary) loaded_q <= 1'b0;
    end
  end

  // --------------------------------------------------------- core, output
  wire [W-1:0] unused_x, unused_y, unused_z;
  wire [W+1:0] unused_exy, unused_exz, unused_eyz;
  wire dir_x, dir_y, dir_z;
  interp3_core #(.W(W)) u_core (
      .i_clk(i_clk), .i_rst(i_rst | abort), .i_load(pop),
      .i_xe(q_data[W-1:0]), .i_ye(q_data[2*W:W+1]), .i_ze(q_data[3*W+1:2*W+2]),
      .i_xneg(q_data[W]), .i_yneg(q_data[2*W+1]), .i_zneg(q_data[3*W+2]),
      .i_cmd(cmd), .o_step_x(sx), .o_step_y(sy), .o_step_z(sz),
      .o_dir_x(dir_x), .o_dir_y(dir_y), .o_dir_z(dir_z), .o_done(core_done), .o_ready(core_ready),
      .o_x(unused_x), .o_y(unused_y), .o_z(unused_z), .o_exy(unused_exy), .o_exz(unused_exz), .o_eyz(unused_eyz)
  );

  // The command in flight; the output stage: STEP high for STEP_LEN clocks,
  // then STEP_SPACE clocks low (also after a load: DIR setup) before the next.
  wire [15:0] len1 = (len_q == 16'd0) ? 16'd0 : len_q - 16'd1;
  wire [15:0] space1 = (space_q == 16'd0) ? 16'd0 : space_q - 16'd1;
  always @(posedge i_clk) begin
    if (i_rst || abort) begin
      cmd_q <= 1'b0;
      out_q <= 2'd0;
      ocnt_q <= 16'd0;
      stp_q <= 3'b000;
    end else begin
      cmd_q <= cmd;
      if (strobe) begin
        out_q <= 2'd1;
        ocnt_q <= len1;
        stp_q <= {sz, sy, sx};
      end else if (pop) begin
        out_q <= 2'd2;
        ocnt_q <= space1;
      end else if (out_q != 2'd0) begin
        if (ocnt_q != 16'd0) ocnt_q <= ocnt_q - 16'd1;
        else if (out_q == 2'd1) begin
          out_q <= 2'd2;
          ocnt_q <= space1;
          stp_q <= 3'b000;
        end else out_q <= 2'd0;
      end
    end
  end

  assign o_step_x = stp_q[0];
  assign o_step_y = stp_q[1];
  assign o_step_z = stp_q[2];
  assign o_dir_x = dir_x;
  assign o_dir_y = dir_y;
  assign o_dir_z = dir_z;
  assign o_busy = loaded_q;

  pos_counter #(.PW(32)) u_pos_x (.i_clk(i_clk), .i_rst(i_rst), .i_pulse(sx), .i_neg(dir_x), .o_pos(pos_x));
  pos_counter #(.PW(32)) u_pos_y (.i_clk(i_clk), .i_rst(i_rst), .i_pulse(sy), .i_neg(dir_y), .o_pos(pos_y));
  pos_counter #(.PW(32)) u_pos_z (.i_clk(i_clk), .i_rst(i_rst), .i_pulse(sz), .i_neg(dir_z), .o_pos(pos_z));

  // Read data.
  always @(posedge i_clk) begin
    if (acc & ~i_wb_we) begin
      o_wb_dat <= 32'd0;
      case (adr)
        A_AXIS3_ID: o_wb_dat <= R_AXIS3_ID;
        A_AXIS3_PARAMS: begin
          o_wb_dat[AXIS3_PARAMS_W +: 8] <= W[7:0];
          o_wb_dat[AXIS3_PARAMS_QDEPTH +: 8] <= QDEPTH8;
        end
        A_AXIS3_CTRL: begin
          o_wb_dat[AXIS3_CTRL_RUN] <= run_q;
          o_wb_dat[AXIS3_CTRL_DRAIN] <= drain_q;
        end
        A_AXIS3_STATUS: begin
          o_wb_dat[AXIS3_STATUS_BUSY] <= loaded_q;
          o_wb_dat[AXIS3_STATUS_EMPTY] <= (q_level == 0);
          o_wb_dat[AXIS3_STATUS_FULL] <= q_full;
          o_wb_dat[AXIS3_STATUS_REJECT] <= reject_q;
          o_wb_dat[AXIS3_STATUS_UNDERRUN] <= underrun_q;
          o_wb_dat[AXIS3_STATUS_RUN] <= run_q;
          o_wb_dat[AXIS3_STATUS_LEVEL +: QAW+2] <= q_level;
        end
        A_AXIS3_CYCLE: o_wb_dat[15:0] <= cycle_q;
        A_AXIS3_STEP_LEN: o_wb_dat[15:0] <= len_q;
        A_AXIS3_STEP_SPACE: o_wb_dat[15:0] <= space_q;
        A_AXIS3_CH_X: o_wb_dat <= {{(32-W){chx_q[W]}}, chx_q[W-1:0]};
        A_AXIS3_CH_Y: o_wb_dat <= {{(32-W){chy_q[W]}}, chy_q[W-1:0]};
        A_AXIS3_CH_Z: o_wb_dat <= {{(32-W){chz_q[W]}}, chz_q[W-1:0]};
        A_AXIS3_POS_X: o_wb_dat <= pos_x;
        A_AXIS3_POS_Y: o_wb_dat <= pos_y;
        A_AXIS3_POS_Z: o_wb_dat <= pos_z;
        A_AXIS3_CHORDS: o_wb_dat <= chords_q;
        A_AXIS3_UNDERRUNS: o_wb_dat <= underruns_q;
        default: ;
      endcase
    end
  end

  generate
    if (W < 2 || W > 30 || QAW < 2 || QAW > 7) begin : g_bad_params
      interp3_top_parameters_W_2_to_30_QAW_2_to_7 u_bad ();
    end
  endgenerate

endmodule
