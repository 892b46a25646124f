`default_nettype none
// cpu8085: an Intel 8085 CPU, one clock per T-state, T-state exact against
// the C++ ISS (model/i8085, contract docs/i8085.md; this design docs/cpu8085.md).
//
// Execution is a sequence of units, exactly the ISS's step(): one
// instruction, one interrupt acknowledge, or one halted idle T-state. A unit
// is a list of machine cycles:
//   OF   opcode fetch, 4 or 6 T (6 for INX DCX PCHL SPHL CALL Ccc Rcc RST PUSH)
//   MR MW IOR IOW   3 T memory / I/O read / write
//   INA  interrupt acknowledge (INTR): replaces OF and the operand reads
//   BI   bus idle: 3 T (DAD), or the 6 T first cycle of a TRAP/RST x.5 ack
//   HLT  1 T: the fifth T of HLT, and each idle unit while halted
// The first T-state of a unit decides, from the registered state and the
// pins, what the unit is (interrupt, idle or instruction): that is the
// ISS's sampling point at the start of step().
//
// Bus (synchronous): o_addr / o_dout / o_io are valid for the whole cycle;
// o_rd (memory read or opcode fetch), o_wr and o_inta are one-clock strobes
// in T2. A read is answered by i_din during T3 (the CPU samples it at the
// end of T3), which a synchronous RAM that registers its output at the end
// of T2 does. o_wr is the write itself: the target stores at the end of T2.
//
// Reset: synchronous, active high, i_rst. PC = SP = 0, all registers and F
// 0, IE 0, masks set, latches cleared (as the ISS's reset()).
//
// Debug / retire port: o_retire is high for one clock, the first T-state
// of the next unit, after each unit ends; the o_dbg_* outputs then show the
// state after the unit (the ISS's regs after step()).
module cpu8085 (
    input  wire        i_clk,
    input  wire        i_rst,     // synchronous, active high
    // bus
    output reg  [15:0] o_addr,    // address of the current machine cycle
    output reg  [ 7:0] o_dout,    // write data of the current machine cycle
    input  wire [ 7:0] i_din,     // read data, sampled at the end of T3
    output wire        o_rd,      // T2 strobe: memory read or opcode fetch
    output wire        o_wr,      // T2 strobe: memory or I/O write
    output wire        o_io,      // the current cycle is an I/O cycle
    output wire        o_inta,    // T2 strobe: interrupt acknowledge read
    output wire [ 2:0] o_cycle,   // machine cycle type (CY_* below)
    output wire [ 2:0] o_tstate,  // T-state within the machine cycle, 1..6
    // interrupts and serial pins
    input  wire        i_trap,
    input  wire        i_rst75,
    input  wire        i_rst65,
    input  wire        i_rst55,
    input  wire        i_intr,
    input  wire        i_sid,
    output wire        o_sod,
    output wire        o_halted,
    output wire        o_ie,
    // debug / retire port
    output reg         o_retire,     // one clock after each unit ends
    output wire [ 1:0] o_dbg_kind,   // unit that retired: K_* below
    output wire [ 2:0] o_dbg_irq,    // interrupt acknowledged: IRQ_* below
    output wire [15:0] o_dbg_ipc,    // PC when the unit started
    output wire [ 7:0] o_dbg_op,     // opcode (instructions, INTR acks)
    output wire [15:0] o_dbg_pc,
    output wire [15:0] o_dbg_sp,
    output wire [63:0] o_dbg_regs,   // A F B C D E H L, A in the top byte
    // debug load: while high, a clock loads these instead of running (use
    // at a unit boundary, i.e. while o_retire is high or after reset)
    input  wire        i_dbg_load,
    input  wire [15:0] i_dbg_pc,
    input  wire [15:0] i_dbg_sp,
    input  wire [63:0] i_dbg_regs    // A F B C D E H L, as o_dbg_regs
);
  // Machine cycle types (o_cycle).
  localparam [2:0] CY_OF = 3'd0, CY_MR = 3'd1, CY_MW = 3'd2, CY_IOR = 3'd3;
  localparam [2:0] CY_IOW = 3'd4, CY_INA = 3'd5, CY_BI = 3'd6, CY_HLT = 3'd7;
  // Unit kinds.
  localparam [1:0] K_INSTR = 2'd0, K_IACK = 2'd1, K_INTR = 2'd2, K_IDLE = 2'd3;
  // Interrupts (o_dbg_irq), numbered as the ISS's i8085::Interrupt.
  localparam [2:0] IRQ_NONE = 3'd0, IRQ_TRAP = 3'd1, IRQ_75 = 3'd2, IRQ_65 = 3'd3;
  localparam [2:0] IRQ_55 = 3'd4, IRQ_INTR = 3'd5;
  // Address sources.
  localparam [2:0] A_PC = 3'd0, A_HL = 3'd1, A_BC = 3'd2, A_DE = 3'd3;
  localparam [2:0] A_WZ = 3'd4, A_SP = 3'd5, A_SP1 = 3'd6, A_ZZ = 3'd7;
  // Register file indices: the opcode's register field; 6 (M) holds F.
  localparam [2:0] R_B = 3'd0, R_C = 3'd1, R_D = 3'd2, R_E = 3'd3;
  localparam [2:0] R_H = 3'd4, R_L = 3'd5, R_F = 3'd6, R_A = 3'd7;

  // ---------------------------------------------------------------- state
  // Architectural registers B C D E H L F A (F at the M index).
  reg  [ 7:0] rf      [0:7];
  reg  [15:0] pc_q, sp_q;
  // Instruction register and the temporary pair W Z.
  reg  [ 7:0] ir_q, w_q, z_q;
  // Sequencer: T-state in the cycle (1..6) and cycle index in the unit.
  reg  [ 2:0] t_q, mc_q;
  // Kind of the current unit (valid after its first T-state).
  reg  [ 1:0] kind_q;
  reg  [ 2:0] irq_q;
  reg  [15:0] ipc_q;      // PC at the start of the unit
  reg  [15:0] vec_q;      // TRAP / RST x.5 vector of the current ack
  // Interrupt system.
  reg         ie_q, ei_delay_q, halted_q, sod_q;
  reg  [ 2:0] masks_q;    // M7.5 M6.5 M5.5
  reg         r75_latch_q, r75_prev_q, trap_latch_q, trap_prev_q;
  reg         rim_after_trap_q, ie_before_trap_q;

  wire [ 7:0] reg_a = rf[R_A];
  wire [ 7:0] reg_f = rf[R_F];
  wire [15:0] bc = {rf[R_B], rf[R_C]};
  wire [15:0] de = {rf[R_D], rf[R_E]};
  wire [15:0] hl = {rf[R_H], rf[R_L]};
  wire [15:0] wz = {w_q, z_q};

  wire [2:0] ddd = ir_q[5:3];
  wire [2:0] sss = ir_q[2:0];
  wire [1:0] rp = ir_q[5:4];

  // ------------------------------------------------- interrupt decision
  wire trap_edge = i_trap & ~trap_prev_q;
  wire r75_edge = i_rst75 & ~r75_prev_q;
  wire trap_lat = trap_latch_q | trap_edge;
  wire r75_lat = r75_latch_q | r75_edge;
  wire mask_ok = ie_q & ~ei_delay_q;
  reg  [2:0] irq_now;
  always @* begin
    if (trap_lat & i_trap) irq_now = IRQ_TRAP;
    else if (mask_ok & r75_lat & ~masks_q[2]) irq_now = IRQ_75;
    else if (mask_ok & i_rst65 & ~masks_q[1]) irq_now = IRQ_65;
    else if (mask_ok & i_rst55 & ~masks_q[0]) irq_now = IRQ_55;
    else if (mask_ok & i_intr) irq_now = IRQ_INTR;
    else irq_now = IRQ_NONE;
  end
  // The first T-state of a unit decides its kind.
  wire unit_t1 = (mc_q == 3'd0) && (t_q == 3'd1);
  reg  [1:0] kind_now;
  always @* begin
    if (irq_now == IRQ_INTR) kind_now = K_INTR;
    else if (irq_now != IRQ_NONE) kind_now = K_IACK;
    else if (halted_q) kind_now = K_IDLE;
    else kind_now = K_INSTR;
  end
  // Everything but the sequencer's own registers works from kind_q, valid
  // from the unit's second T-state on: at the first one no cycle of an
  // instruction or acknowledge ends, so the pins' decision (kind_now) only
  // reaches the sequencer, not the datapath (a shorter critical path).
  wire [1:0] kind = kind_q;
  wire intr_mode = (kind == K_INTR);

  // ------------------------------------------------------------ decode
  // Conditions NZ Z NC C PO PE P M.
  reg cond;
  always @* begin
    case (ddd)
      3'd0: cond = ~reg_f[6];
      3'd1: cond = reg_f[6];
      3'd2: cond = ~reg_f[0];
      3'd3: cond = reg_f[0];
      3'd4: cond = ~reg_f[2];
      3'd5: cond = reg_f[2];
      3'd6: cond = ~reg_f[7];
      default: cond = reg_f[7];
    endcase
  end

  // Opcode fetches of 6 T-states.
  reg of6;
  always @* begin
    casez (ir_q)
      8'b00??0011, 8'b00??1011: of6 = 1'b1;  // INX DCX
      8'b11101001, 8'b11111001: of6 = 1'b1;  // PCHL SPHL
      8'b11001101, 8'b11???100: of6 = 1'b1;  // CALL Ccc
      8'b11???000, 8'b11???111: of6 = 1'b1;  // Rcc RST
      8'b11??0101: of6 = 1'b1;  // PUSH
      default: of6 = 1'b0;
    endcase
  end

  // The machine cycle sequence: for the current unit and cycle index, the
  // cycle type, its address and write data source, and whether it is the
  // unit's last cycle.
  reg [2:0] seq_cyc, seq_asel;
  reg       seq_last;
  reg [7:0] seq_dout;
  // Register pair of LXI / DAD / INX / DCX / PUSH / POP (3: SP).
  wire [15:0] rp_val = (rp == 2'd0) ? bc : (rp == 2'd1) ? de : (rp == 2'd2) ? hl : sp_q;
  wire [7:0] push_hi = (rp == 2'd3) ? reg_a : rf[{rp, 1'b0}];
  wire [7:0] push_lo = (rp == 2'd3) ? reg_f : rf[{rp, 1'b1}];
  // The casez blocks below are priority decoders: an earlier, narrower
  // pattern (HLT, M operands) wins over a later, wider one.
  /* verilator lint_off CASEOVERLAP */
  always @* begin
    seq_cyc  = CY_MR;
    seq_asel = A_PC;
    seq_last = 1'b1;
    seq_dout = reg_a;
    if (mc_q == 3'd0) begin
      case (kind)
        K_IACK: begin
          seq_cyc  = CY_BI;
          seq_last = 1'b0;
        end
        K_IDLE: seq_cyc = CY_HLT;
        K_INTR: begin
          seq_cyc  = CY_INA;
          seq_last = 1'b1;
        end
        default: seq_cyc = CY_OF;
      endcase
      if (kind != K_IACK && kind != K_IDLE) begin
        // Does the instruction continue past its opcode fetch?
        casez (ir_q)
          8'b01110110: seq_last = 1'b0;  // HLT
          8'b01110???, 8'b01???110: seq_last = 1'b0;  // MOV M,r / MOV r,M
          8'b10???110, 8'b11???110: seq_last = 1'b0;  // ALU M / ALU imm
          8'b00???110, 8'b0011010?: seq_last = 1'b0;  // MVI, INR M, DCR M
          8'b00??0001, 8'b00??1001: seq_last = 1'b0;  // LXI DAD
          8'b000?0010, 8'b000?1010: seq_last = 1'b0;  // STAX LDAX
          8'b001??010: seq_last = 1'b0;  // SHLD LHLD STA LDA
          8'b11???000: seq_last = ~cond;  // Rcc
          8'b11001001, 8'b11??0001: seq_last = 1'b0;  // RET POP
          8'b11???010, 8'b11000011: seq_last = 1'b0;  // Jcc JMP
          8'b11010011, 8'b11011011, 8'b11100011: seq_last = 1'b0;  // OUT IN XTHL
          8'b11???100, 8'b11001101: seq_last = 1'b0;  // Ccc CALL
          8'b11??0101, 8'b11???111: seq_last = 1'b0;  // PUSH RST
          default: seq_last = 1'b1;
        endcase
      end
    end else begin
      casez (ir_q)
        8'b01110110: seq_cyc = CY_HLT;  // HLT: its fifth T-state
        8'b01110???: begin  // MOV M,r
          seq_cyc  = CY_MW;
          seq_asel = A_HL;
          seq_dout = rf[sss];
        end
        8'b01???110, 8'b10???110: seq_asel = A_HL;  // MOV r,M / ALU M
        8'b11???110: ;  // ALU imm
        8'b00110110, 8'b0011010?: begin  // MVI M / INR M / DCR M
          seq_asel = (ir_q == 8'h36 && mc_q == 3'd1) ? A_PC : A_HL;
          seq_cyc  = (mc_q == 3'd1) ? CY_MR : CY_MW;
          seq_dout = z_q;
          seq_last = (mc_q == 3'd2);
        end
        8'b00???110: ;  // MVI r
        8'b00??0001: seq_last = (mc_q == 3'd2);  // LXI
        8'b00??1001: begin  // DAD: two bus idle cycles
          seq_cyc  = CY_BI;
          seq_last = (mc_q == 3'd2);
        end
        8'b000?0010: begin  // STAX
          seq_cyc  = CY_MW;
          seq_asel = ir_q[4] ? A_DE : A_BC;
        end
        8'b000?1010: seq_asel = ir_q[4] ? A_DE : A_BC;  // LDAX
        8'b001??010: begin  // SHLD LHLD STA LDA
          seq_asel = (mc_q <= 3'd2) ? A_PC : A_WZ;
          seq_cyc  = (mc_q <= 3'd2 || ir_q[3]) ? CY_MR : CY_MW;
          seq_dout = (ir_q[4]) ? reg_a : (mc_q == 3'd3) ? rf[R_L] : rf[R_H];
          seq_last = (mc_q == (ir_q[4] ? 3'd3 : 3'd4));
        end
        8'b11???000, 8'b11001001, 8'b11??0001: begin  // Rcc RET POP
          seq_asel = A_SP;
          seq_last = (mc_q == 3'd2);
        end
        8'b11???010: seq_last = (mc_q == 3'd2) || !cond;  // Jcc
        8'b11000011: seq_last = (mc_q == 3'd2);  // JMP
        8'b11010011, 8'b11011011: begin  // OUT IN
          seq_asel = (mc_q == 3'd1) ? A_PC : A_ZZ;
          seq_cyc  = (mc_q == 3'd1) ? CY_MR : (ir_q[3] ? CY_IOR : CY_IOW);
          seq_last = (mc_q == 3'd2);
        end
        8'b11100011: begin  // XTHL
          seq_asel = (mc_q == 3'd1 || mc_q == 3'd4) ? A_SP : A_SP1;
          seq_cyc  = (mc_q <= 3'd2) ? CY_MR : CY_MW;
          seq_dout = (mc_q == 3'd3) ? rf[R_H] : rf[R_L];
          seq_last = (mc_q == 3'd4);
        end
        8'b11???100, 8'b11001101: begin  // Ccc CALL
          seq_asel = (mc_q <= 3'd2) ? A_PC : A_SP;
          seq_cyc  = (mc_q <= 3'd2) ? CY_MR : CY_MW;
          seq_dout = (mc_q == 3'd3) ? pc_q[15:8] : pc_q[7:0];
          seq_last = (mc_q == 3'd4) || (mc_q == 3'd1 && !ir_q[0] && !cond);
        end
        8'b11??0101: begin  // PUSH
          seq_cyc  = CY_MW;
          seq_asel = A_SP;
          seq_dout = (mc_q == 3'd1) ? push_hi : push_lo;
          seq_last = (mc_q == 3'd2);
        end
        8'b11???111: begin  // RST (and the TRAP / RST x.5 acknowledge)
          seq_cyc  = CY_MW;
          seq_asel = A_SP;
          seq_dout = (mc_q == 3'd1) ? pc_q[15:8] : pc_q[7:0];
          seq_last = (mc_q == 3'd2);
        end
        default: ;
      endcase
      // INTR acknowledge: operand bytes come from INTA cycles.
      if (intr_mode && seq_cyc == CY_MR && seq_asel == A_PC) seq_cyc = CY_INA;
    end
  end
  /* verilator lint_on CASEOVERLAP */

  // Cycle length and ends.
  reg [2:0] cyc_len;
  always @* begin
    if (mc_q == 3'd0) begin
      case (kind)
        K_IACK: cyc_len = 3'd6;
        K_IDLE: cyc_len = 3'd1;
        default: cyc_len = of6 ? 3'd6 : 3'd4;
      endcase
    end else begin
      cyc_len = (seq_cyc == CY_HLT) ? 3'd1 : 3'd3;
    end
  end
  // The opcode is known from T4 on; before that no fetch can end.
  wire of_early = (mc_q == 3'd0) && (kind == K_INSTR || kind == K_INTR) && (t_q < 3'd4);
  // At a unit's first T-state only an idle unit ends (and does no work).
  wire cyc_end_later = !unit_t1 && !of_early && (t_q == cyc_len);
  wire cyc_end = unit_t1 ? (kind_now == K_IDLE) : cyc_end_later;
  wire unit_end = unit_t1 ? (kind_now == K_IDLE) : (cyc_end_later && seq_last);

  // Bus outputs.
  always @* begin
    case (seq_asel)
      A_HL: o_addr = hl;
      A_BC: o_addr = bc;
      A_DE: o_addr = de;
      A_WZ: o_addr = wz;
      A_SP: o_addr = sp_q;
      A_SP1: o_addr = sp_q + 16'd1;
      A_ZZ: o_addr = {z_q, z_q};
      default: o_addr = pc_q;
    endcase
    o_dout = seq_dout;
  end
  wire is_t2 = (t_q == 3'd2);
  assign o_rd = is_t2 && (seq_cyc == CY_OF || seq_cyc == CY_MR || seq_cyc == CY_IOR);
  assign o_wr = is_t2 && (seq_cyc == CY_MW || seq_cyc == CY_IOW);
  assign o_io = (seq_cyc == CY_IOR || seq_cyc == CY_IOW);
  assign o_inta = is_t2 && (seq_cyc == CY_INA);
  // At a unit's first T-state the cycle type follows the decision.
  reg [2:0] t1_cyc;
  always @* begin
    case (kind_now)
      K_IACK: t1_cyc = CY_BI;
      K_IDLE: t1_cyc = CY_HLT;
      K_INTR: t1_cyc = CY_INA;
      default: t1_cyc = CY_OF;
    endcase
  end
  assign o_cycle = unit_t1 ? t1_cyc : seq_cyc;
  assign o_tstate = t_q;

  // ----------------------------------------------------------------- ALU
  reg  [4:0] alu_op;
  reg  [7:0] alu_b;
  wire [7:0] alu_res, alu_f;
  always @* begin
    alu_op = {2'b00, ddd};
    alu_b  = (sss == 3'd6) ? i_din : rf[sss];
    if (ir_q[7:6] == 2'b00) begin
      alu_b = (ddd == 3'd6) ? i_din : rf[ddd];
      case (sss)
        3'b100:  alu_op = 5'd8;  // INR
        3'b101:  alu_op = 5'd9;  // DCR
        default: alu_op = 5'd10 + {2'b00, ddd};  // RLC RRC RAL RAR DAA CMA STC CMC
      endcase
    end
  end
  cpu8085_alu u_alu (
      .i_op (alu_op),
      .i_a  (reg_a),
      .i_b  (alu_b),
      .i_f  (reg_f),
      .o_res(alu_res),
      .o_f  (alu_f)
  );

  wire [16:0] dad_sum = {1'b0, hl} + {1'b0, rp_val};
  wire [15:0] rp_inc = rp_val + 16'd1;
  wire [15:0] rp_dec = rp_val - 16'd1;
  wire [ 7:0] rim_val = {i_sid, r75_lat, i_rst65, i_rst55,
                         rim_after_trap_q ? ie_before_trap_q : ie_q, masks_q};

  // Writes a register pair (rp 3: SP).
  task set_rp;
    input [1:0] which;
    input [15:0] v;
    begin
      case (which)
        2'd0: begin rf[R_B] <= v[15:8]; rf[R_C] <= v[7:0]; end
        2'd1: begin rf[R_D] <= v[15:8]; rf[R_E] <= v[7:0]; end
        2'd2: begin rf[R_H] <= v[15:8]; rf[R_L] <= v[7:0]; end
        default: sp_q <= v;
      endcase
    end
  endtask

  // ---------------------------------------------------- the one sequencer
  // Every architectural and sequencing register; updates happen at the end
  // of the T-state named in each comment.
  integer k;
  // Priority decoders again (see above).
  /* verilator lint_off CASEOVERLAP */
  always @(posedge i_clk) begin
    if (i_rst) begin
      for (k = 0; k < 8; k = k + 1) rf[k] <= 8'h00;
      pc_q <= 16'h0000;
      sp_q <= 16'h0000;
      ir_q <= 8'h00;
      w_q <= 8'h00;
      z_q <= 8'h00;
      t_q <= 3'd1;
      mc_q <= 3'd0;
      kind_q <= K_INSTR;
      irq_q <= IRQ_NONE;
      ipc_q <= 16'h0000;
      vec_q <= 16'h0000;
      ie_q <= 1'b0;
      ei_delay_q <= 1'b0;
      halted_q <= 1'b0;
      sod_q <= 1'b0;
      masks_q <= 3'b111;
      r75_latch_q <= 1'b0;
      r75_prev_q <= 1'b0;
      trap_latch_q <= 1'b0;
      trap_prev_q <= 1'b0;
      rim_after_trap_q <= 1'b0;
      ie_before_trap_q <= 1'b0;
      o_retire <= 1'b0;
    end else if (i_dbg_load) begin
      {rf[R_A], rf[R_F], rf[R_B], rf[R_C], rf[R_D], rf[R_E], rf[R_H], rf[R_L]} <= i_dbg_regs;
      pc_q <= i_dbg_pc;
      sp_q <= i_dbg_sp;
    end else begin
      o_retire <= 1'b0;
      // Pin edges latch at any time.
      trap_prev_q <= i_trap;
      r75_prev_q <= i_rst75;
      trap_latch_q <= trap_lat;
      r75_latch_q <= r75_lat;

      // Sequencing.
      if (unit_end) begin
        t_q <= 3'd1;
        mc_q <= 3'd0;
        o_retire <= 1'b1;
      end else if (cyc_end) begin
        t_q <= 3'd1;
        mc_q <= mc_q + 3'd1;
      end else begin
        t_q <= t_q + 3'd1;
      end

      // First T-state of a unit: what it is.
      if (unit_t1) begin
        kind_q <= kind_now;
        irq_q <= irq_now;
        ipc_q <= pc_q;
        ei_delay_q <= 1'b0;
        if (kind_now == K_IACK || kind_now == K_INTR) begin
          ie_q <= 1'b0;
          halted_q <= 1'b0;
        end
        if (kind_now == K_IACK) ir_q <= 8'hFF;  // run as an RST
        case (irq_now)
          IRQ_TRAP: begin
            vec_q <= 16'h0024;
            trap_latch_q <= 1'b0;
            ie_before_trap_q <= ie_q;
            rim_after_trap_q <= 1'b1;
          end
          IRQ_75: begin
            vec_q <= 16'h003C;
            r75_latch_q <= 1'b0;
          end
          IRQ_65: vec_q <= 16'h0034;
          default: vec_q <= 16'h002C;
        endcase
      end

      // Opcode fetch / INTA: the opcode arrives at the end of T3.
      if (mc_q == 3'd0 && t_q == 3'd3 && (kind == K_INSTR || kind == K_INTR)) begin
        ir_q <= i_din;
        if (kind == K_INSTR) pc_q <= pc_q + 16'd1;
      end

      // End of a machine cycle: the instruction's work.
      if (cyc_end_later && kind != K_IDLE) begin
        if (mc_q == 3'd0) begin
          // ---- end of the opcode fetch
          casez (ir_q)
            8'b01110110: ;  // HLT: see its HLT cycle
            8'b01??????: if (ddd != 3'd6 && sss != 3'd6) rf[ddd] <= rf[sss];  // MOV r,r
            8'b10??????: begin  // ALU r
              if (sss != 3'd6) begin
                if (ddd != 3'd7) rf[R_A] <= alu_res;
                rf[R_F] <= alu_f;
              end
            end
            8'b00???10?: begin  // INR r / DCR r
              if (ddd != 3'd6) begin
                rf[ddd] <= alu_res;
                rf[R_F] <= alu_f;
              end
            end
            8'b00???111: begin  // rotates DAA CMA STC CMC
              rf[R_A] <= alu_res;
              rf[R_F] <= alu_f;
            end
            8'b00??0011: set_rp(rp, rp_inc);  // INX
            8'b00??1011: set_rp(rp, rp_dec);  // DCX
            8'b00100000: begin  // RIM
              rf[R_A] <= rim_val;
              rim_after_trap_q <= 1'b0;
            end
            8'b00110000: begin  // SIM
              if (reg_a[3]) masks_q <= reg_a[2:0];
              if (reg_a[4]) r75_latch_q <= 1'b0;
              if (reg_a[6]) sod_q <= reg_a[7];
            end
            8'b11101011: begin  // XCHG
              rf[R_D] <= rf[R_H];
              rf[R_E] <= rf[R_L];
              rf[R_H] <= rf[R_D];
              rf[R_L] <= rf[R_E];
            end
            8'b11101001: pc_q <= hl;  // PCHL
            8'b11111001: sp_q <= hl;  // SPHL
            8'b11110011: begin  // DI
              ie_q <= 1'b0;
              ei_delay_q <= 1'b0;
            end
            8'b11111011: begin  // EI
              ie_q <= 1'b1;
              ei_delay_q <= 1'b1;
            end
            8'b11??0101, 8'b11???111: sp_q <= sp_q - 16'd1;  // PUSH RST (and acks)
            default: ;
          endcase
        end else begin
          // ---- end of a later machine cycle
          if ((seq_cyc == CY_MR) && (seq_asel == A_PC)) pc_q <= pc_q + 16'd1;
          casez (ir_q)
            8'b01110110: halted_q <= 1'b1;  // HLT
            8'b01110???: ;  // MOV M,r
            8'b01???110: rf[ddd] <= i_din;  // MOV r,M
            8'b10???110, 8'b11???110: begin  // ALU M / ALU imm
              if (ddd != 3'd7) rf[R_A] <= alu_res;
              rf[R_F] <= alu_f;
            end
            8'b00110110: if (mc_q == 3'd1) z_q <= i_din;  // MVI M
            8'b0011010?: begin  // INR M / DCR M
              if (mc_q == 3'd1) begin
                z_q <= alu_res;
                rf[R_F] <= alu_f;
              end
            end
            8'b00???110: rf[ddd] <= i_din;  // MVI r
            8'b00??0001: begin  // LXI
              if (mc_q == 3'd1) z_q <= i_din;
              else set_rp(rp, {i_din, z_q});
            end
            8'b00??1001: begin  // DAD
              if (mc_q == 3'd2) begin
                rf[R_H] <= dad_sum[15:8];
                rf[R_L] <= dad_sum[7:0];
                rf[R_F] <= {reg_f[7:1], dad_sum[16]};
              end
            end
            8'b000?0010: ;  // STAX
            8'b000?1010: rf[R_A] <= i_din;  // LDAX
            8'b001??010: begin  // SHLD LHLD STA LDA
              case (mc_q)
                3'd1: z_q <= i_din;
                3'd2: w_q <= i_din;
                3'd3: begin
                  if (ir_q[4]) begin
                    if (ir_q[3]) rf[R_A] <= i_din;  // LDA
                  end else begin
                    if (ir_q[3]) rf[R_L] <= i_din;  // LHLD
                    {w_q, z_q} <= wz + 16'd1;
                  end
                end
                default: if (ir_q[3]) rf[R_H] <= i_din;  // LHLD
              endcase
            end
            8'b11???000, 8'b11001001, 8'b11??0001: begin  // Rcc RET POP
              sp_q <= sp_q + 16'd1;
              if (mc_q == 3'd1) z_q <= i_din;
              else if (ir_q[0] && ir_q[3:0] != 4'b1001) begin  // POP
                if (rp == 2'd3) begin
                  rf[R_A] <= i_din;
                  rf[R_F] <= z_q & 8'hD5;
                end else begin
                  rf[{rp, 1'b0}] <= i_din;
                  rf[{rp, 1'b1}] <= z_q;
                end
              end else pc_q <= {i_din, z_q};  // RET / Rcc
            end
            8'b11???010, 8'b11000011: begin  // Jcc JMP
              if (mc_q == 3'd1) begin
                z_q <= i_din;
                // Jcc not taken: skip the high byte without reading it.
                if (!ir_q[0] && !cond && !intr_mode) pc_q <= pc_q + 16'd2;
              end else pc_q <= {i_din, z_q};
            end
            8'b11010011: if (mc_q == 3'd1) z_q <= i_din;  // OUT
            8'b11011011: begin  // IN
              if (mc_q == 3'd1) z_q <= i_din;
              else rf[R_A] <= i_din;
            end
            8'b11100011: begin  // XTHL
              case (mc_q)
                3'd1: z_q <= i_din;
                3'd2: w_q <= i_din;
                3'd3: ;
                default: begin
                  rf[R_H] <= w_q;
                  rf[R_L] <= z_q;
                end
              endcase
            end
            8'b11???100, 8'b11001101: begin  // Ccc CALL
              case (mc_q)
                3'd1: begin
                  z_q <= i_din;
                  if (!ir_q[0] && !cond && !intr_mode) pc_q <= pc_q + 16'd2;
                end
                3'd2: begin
                  w_q <= i_din;
                  sp_q <= sp_q - 16'd1;
                end
                3'd3: sp_q <= sp_q - 16'd1;
                default: pc_q <= wz;
              endcase
            end
            8'b11??0101: if (mc_q == 3'd1) sp_q <= sp_q - 16'd1;  // PUSH
            8'b11???111: begin  // RST / acknowledge
              if (mc_q == 3'd1) sp_q <= sp_q - 16'd1;
              else pc_q <= (kind == K_IACK) ? vec_q : {10'b0, ddd, 3'b000};
            end
            default: ;
          endcase
        end
      end
    end
  end

  /* verilator lint_on CASEOVERLAP */

  // ---------------------------------------------------------------- debug
  assign o_sod = sod_q;
  assign o_halted = halted_q;
  assign o_ie = ie_q;
  assign o_dbg_kind = kind_q;
  assign o_dbg_irq = irq_q;
  assign o_dbg_ipc = ipc_q;
  assign o_dbg_op = ir_q;
  assign o_dbg_pc = pc_q;
  assign o_dbg_sp = sp_q;
  assign o_dbg_regs = {rf[R_A], rf[R_F], rf[R_B], rf[R_C], rf[R_D], rf[R_E], rf[R_H], rf[R_L]};
endmodule

`default_nettype wire
