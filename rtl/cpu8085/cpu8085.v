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
    output reg         o_rd,      // T2 strobe: memory read or opcode fetch
    output reg         o_wr,      // T2 strobe: memory or I/O write
    output reg         o_io,      // the current cycle is an I/O cycle
    output reg         o_inta,    // T2 strobe: interrupt acknowledge read
    output reg  [ 2:0] o_cycle,   // machine cycle type (CY_* below)
    output reg  [ 2:0] o_tstate,  // T-state within the machine cycle, 1..6
    // interrupts and serial pins
    input  wire        i_trap,
    input  wire        i_rst75,
    input  wire        i_rst65,
    input  wire        i_rst55,
    input  wire        i_intr,
    input  wire        i_sid,
    output reg         o_sod,
    output reg         o_halted,
    output reg         o_ie,
    // debug / retire port
    output reg         o_retire,     // one clock after each unit ends
    output reg  [ 1:0] o_dbg_kind,   // unit that retired: K_* below
    output reg  [ 2:0] o_dbg_irq,    // interrupt acknowledged: IRQ_* below
    output reg  [15:0] o_dbg_ipc,    // PC when the unit started
    output reg  [ 7:0] o_dbg_op,     // opcode (instructions, INTR acks)
    output reg  [15:0] o_dbg_pc,
    output reg  [15:0] o_dbg_sp,
    output reg  [63:0] o_dbg_regs,   // A F B C D E H L, A in the top byte
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
  // The byte of o_dbg_regs (below) that holds register i: B C D E H L at 5..0,
  // F at 6, A at 7.
  function [2:0] rf_pos;
    input [2:0] i;
    begin
      rf_pos = (i[2:1] == 2'b11) ? i : 3'd5 - i;
    end
  endfunction
  // The ALU: alu_exec() and its ALU_* operation codes.
`include "cpu8085_alu.vh"

  // ---------------------------------------------------------------- state
  // Every output is a register itself, the registers that a status or
  // debug port shows included, under the port's name: the register file
  // o_dbg_regs, PC o_dbg_pc, SP o_dbg_sp, the instruction register
  // o_dbg_op, the unit's kind o_dbg_kind, its interrupt o_dbg_irq and
  // start PC o_dbg_ipc, the sequencer's T-state o_tstate and cycle type
  // o_cycle, IE o_ie, HALT o_halted (and the bus outputs). A Verilated
  // model copies a register that drives an output port into the port at
  // every clock (and computes a renaming wire read in the block that
  // writes its source at every clock too: no `wire pc_q = o_dbg_pc`).
  //
  // Architectural registers B C D E H L F A (F at the M index), indexed
  // by the R_* below, in one vector o_dbg_regs (A F B C D E H L, A in the
  // top byte): r8(i) reads register i (a Verilated model does not
  // assemble the port at every clock, and keeps no delayed-write flags
  // per array element).
  localparam RF_A = 56, RF_F = 48;  // bit offsets of A and F in o_dbg_regs
  function [7:0] r8;
    input [2:0] i;
    begin
      r8 = o_dbg_regs[{rf_pos(i), 3'b000} +: 8];
    end
  endfunction
  // The temporary pair W Z.
  reg  [ 7:0] w_q, z_q;
  // Sequencer: cycle index in the unit (the T-state in the cycle, 1..6:
  // o_tstate).
  reg  [ 2:0] mc_q;
  reg  [15:0] vec_q;      // TRAP / RST x.5 vector of the current ack
  // Interrupt system.
  reg         ei_delay_q;
  reg  [ 2:0] masks_q;    // M7.5 M6.5 M5.5
  reg         r75_latch_q, r75_prev_q, trap_latch_q, trap_prev_q;
  reg         rim_after_trap_q, ie_before_trap_q;

  // Register pairs and A / F are written out at their uses (r8(R_A),
  // {r8(R_H), r8(R_L)}, ...), not as wires: a Verilated model computes a
  // wire read in several places at every clock, a use inside a clocked
  // block's rare branch only when that branch runs.

  // The opcode's fields DDD (o_dbg_op[5:3]), SSS ([2:0]) and RP ([5:4])
  // are written out at their uses too (the block that reads them writes
  // the instruction register).

  // ------------------------------------------------- interrupt decision
  // Taken at a unit's first T-state only (the ISS's sampling point): these
  // functions are called inside the clocked blocks below under unit_t1, so
  // that no logic follows the pins at every clock.
  // The interrupt a unit starting now acknowledges, from the pins and the
  // registered state: TRAP (latched edge and still high), then, if IE and
  // not in the EI shadow, RST 7.5 (latch) / 6.5 / 5.5 (levels) under their
  // masks, then INTR; IRQ_NONE otherwise.
  function [2:0] irq_decide;
    input trap, rst75, rst65, rst55, intr;
    reg mask_ok;
    begin
      mask_ok = o_ie & ~ei_delay_q;
      if ((trap_latch_q | ~trap_prev_q) & trap) irq_decide = IRQ_TRAP;
      else if (mask_ok & (r75_latch_q | (rst75 & ~r75_prev_q)) & ~masks_q[2]) irq_decide = IRQ_75;
      else if (mask_ok & rst65 & ~masks_q[1]) irq_decide = IRQ_65;
      else if (mask_ok & rst55 & ~masks_q[0]) irq_decide = IRQ_55;
      else if (mask_ok & intr) irq_decide = IRQ_INTR;
      else irq_decide = IRQ_NONE;
    end
  endfunction
  // The kind of a unit acknowledging irq.
  function [1:0] kind_of;
    input [2:0] irq;
    begin
      if (irq == IRQ_INTR) kind_of = K_INTR;
      else if (irq != IRQ_NONE) kind_of = K_IACK;
      else if (o_halted) kind_of = K_IDLE;
      else kind_of = K_INSTR;
    end
  endfunction
  // The first T-state of a unit (registered: the sequencer sets it when a
  // unit ends).
  reg unit_t1;
  // Everything but the sequencer's own registers works from o_dbg_kind, valid
  // from the unit's second T-state on: at the first one no cycle of an
  // instruction or acknowledge ends, so the pins' decision only reaches
  // the sequencer, not the datapath (a shorter critical path).

  // ------------------------------------------------------------ decode
  // The opcode decoded into its class (cpu8085_decode.vh), registered with
  // the instruction register, once per instruction, as a number: the
  // sequencer and the work dispatch on it by one case each.
`include "cpu8085_decode.vh"
  reg [ 5:0] cix_q;  // the class as a number (C_*): class_of(decode(opcode))

  // Conditions NZ Z NC C PO PE P M of the opcode's bits 5:3 on the flags
  // S Z P CY (F's bits 7 6 2 0).
  function cond_of;
    input [2:0] ccc;
    input [3:0] szpc;
    begin
      case (ccc)
        3'd0: cond_of = ~szpc[2];
        3'd1: cond_of = szpc[2];
        3'd2: cond_of = ~szpc[0];
        3'd3: cond_of = szpc[0];
        3'd4: cond_of = ~szpc[1];
        3'd5: cond_of = szpc[1];
        3'd6: cond_of = ~szpc[3];
        default: cond_of = szpc[3];
      endcase
    end
  endfunction
  // The condition ccc (an opcode's bits 5:3) on the current flags (no conditional
  // instruction changes F).
  function cond_ir;
    input [2:0] ccc;
    begin
      cond_ir = cond_of(ccc, {o_dbg_regs[RF_F + 7], o_dbg_regs[RF_F + 6], o_dbg_regs[RF_F + 2], o_dbg_regs[RF_F + 0]});
    end
  endfunction

  // ------------------------------------------------ machine cycle sequence
  // The cycle after the opcode fetch, cycle index mc = 1..4, of the current
  // unit: its type, address and write data sources, and whether it is the
  // unit's last cycle; the data sheet's cycle list of each class, one case
  // on the class index. The sequencer registers them when the cycle starts
  // (o_cycle, asel_q, dsel_q, last_q): they are computed once per cycle,
  // not at every clock.
  // Write data sources.
  localparam [3:0] D_A = 4'd0, D_SSS = 4'd1, D_Z = 4'd2, D_L = 4'd3, D_H = 4'd4;
  localparam [3:0] D_PCH = 4'd5, D_PCL = 4'd6, D_PUSH_HI = 4'd7, D_PUSH_LO = 4'd8;

  // {cycle type, address source, write data source, last}. Jcc / Ccc end
  // after their first operand byte when the condition fails; an INTR
  // acknowledge reads its operand bytes by INTA cycles.
  function [10:0] seq_next;
    input [2:0] mc;
    reg at_1, at_2, at_3, at_4, at_le2;
    reg [2:0] cyc, asel;
    reg [3:0] dsel;
    reg last;
    begin
      {at_1, at_2, at_3, at_4} = {mc == 3'd1, mc == 3'd2, mc == 3'd3, mc == 3'd4};
      at_le2 = (mc <= 3'd2);
      {cyc, asel, dsel, last} = {CY_MR, A_PC, D_A, 1'b1};
      case (cix_q)
        C_HLT: cyc = CY_HLT;  // its fifth T-state
        C_MOV_MR: {cyc, asel, dsel} = {CY_MW, A_HL, D_SSS};
        C_MOV_RM, C_ALU_M: asel = A_HL;
        C_MVI_M: {cyc, asel, dsel, last} = {at_1 ? CY_MR : CY_MW, at_1 ? A_PC : A_HL, D_Z, at_2};
        C_INCDEC_M: {cyc, asel, dsel, last} = {at_1 ? CY_MR : CY_MW, A_HL, D_Z, at_2};
        C_LXI: last = at_2;
        C_DAD: {cyc, last} = {CY_BI, at_2};  // two bus idle cycles
        C_STAX: {cyc, asel} = {CY_MW, o_dbg_op[4] ? A_DE : A_BC};
        C_LDAX: asel = o_dbg_op[4] ? A_DE : A_BC;
        C_DIRECT: begin  // STA LDA: address, one byte; SHLD LHLD: address, two bytes
          {cyc, asel, last} = {(at_le2 || o_dbg_op[3]) ? CY_MR : CY_MW, at_le2 ? A_PC : A_WZ, o_dbg_op[4] ? at_3 : at_4};
          dsel = o_dbg_op[4] ? D_A : at_3 ? D_L : D_H;
        end
        C_RCC, C_RET, C_POP: {asel, last} = {A_SP, at_2};
        C_JCC: last = at_2 || !cond_ir(o_dbg_op[5:3]);
        C_JMP: last = at_2;
        C_OUT: {cyc, asel, last} = {at_1 ? CY_MR : CY_IOW, at_1 ? A_PC : A_ZZ, at_2};
        C_IN: {cyc, asel, last} = {at_1 ? CY_MR : CY_IOR, at_1 ? A_PC : A_ZZ, at_2};
        C_XTHL: begin  // H to SP+1 first
          {cyc, asel, dsel} = {at_le2 ? CY_MR : CY_MW, (at_1 || at_4) ? A_SP : A_SP1, at_3 ? D_H : D_L};
          last = at_4;  // XTHL: MR MR MW MW
        end
        C_CCC, C_CALL: begin
          {cyc, asel, dsel} = {at_le2 ? CY_MR : CY_MW, at_le2 ? A_PC : A_SP, at_3 ? D_PCH : D_PCL};
          last = at_4 || (at_1 && cix_q == C_CCC && !cond_ir(o_dbg_op[5:3]));
        end
        C_PUSH: {cyc, asel, dsel, last} = {CY_MW, A_SP, at_1 ? D_PUSH_HI : D_PUSH_LO, at_2};
        C_RST: {cyc, asel, dsel, last} = {CY_MW, A_SP, at_1 ? D_PCH : D_PCL, at_2};
        default: ;  // the classes done with their fetch never get here
      endcase
      if (o_dbg_kind == K_INTR && cyc == CY_MR && asel == A_PC) cyc = CY_INA;
      seq_next = {cyc, asel, dsel, last};
    end
  endfunction

  // The opcode fetch's length and whether the unit ends with it (Rcc when
  // its condition fails), for opcode op.
  function [3:0] of_end;  // {length, last}
    input [7:0] op;
    reg of6, of_only, rcc;
    begin
      {of6, of_only, rcc} = decode_of(op);
      of_end = {of6 ? 3'd6 : 3'd4, of_only | (rcc & ~cond_ir(op[5:3]))};
    end
  endfunction

  // The current cycle, registered when it starts: type, address and write
  // data sources, length in T-states, last of the unit.
  reg [2:0] asel_q, len_q;
  reg [3:0] dsel_q;
  reg       last_q;
  // (A cycle ends at its last T-state: o_tstate == len_q, but at a unit's first
  // T-state, where only an idle unit ends. The opcode arrives at the end of
  // T3 of the opcode fetch / INTA. Both are tested in the clocked block
  // below, where they are needed, not computed as wires at every clock.)

  // Bus outputs: the address and write data, registered by the sequencer
  // at the end of a cycle's first T-state from its sources (valid from T2,
  // the strobes' T-state, to the cycle's end).
  function [15:0] addr_of;
    input [2:0] asel;
    begin
      case (asel)
        A_HL: addr_of = {r8(R_H), r8(R_L)};
        A_BC: addr_of = {r8(R_B), r8(R_C)};
        A_DE: addr_of = {r8(R_D), r8(R_E)};
        A_WZ: addr_of = {w_q, z_q};
        A_SP: addr_of = o_dbg_sp;
        A_SP1: addr_of = o_dbg_sp + 16'd1;
        A_ZZ: addr_of = {z_q, z_q};
        default: addr_of = o_dbg_pc;
      endcase
    end
  endfunction
  function [7:0] dout_of;
    input [3:0] dsel;
    begin
      case (dsel)
        D_SSS: dout_of = r8(o_dbg_op[2:0]);
        D_Z: dout_of = z_q;
        D_L: dout_of = r8(R_L);
        D_H: dout_of = r8(R_H);
        D_PCH: dout_of = o_dbg_pc[15:8];
        D_PCL: dout_of = o_dbg_pc[7:0];
        D_PUSH_HI: dout_of = (o_dbg_op[5:4] == 2'd3) ? r8(R_A) : r8({o_dbg_op[5:4], 1'b0});
        D_PUSH_LO: dout_of = (o_dbg_op[5:4] == 2'd3) ? r8(R_F) : r8({o_dbg_op[5:4], 1'b1});
        default: dout_of = r8(R_A);
      endcase
    end
  endfunction
  // During a unit's first T-state the unit's kind is not decided yet (the
  // pins decide it at the end of that T-state): o_cycle shows CY_OF then
  // (CY_HLT while halted), its own type from the second T-state on.

  // ----------------------------------------------------------------- ALU
  // The ALU operation of instruction ir on operand b (its register or the
  // byte read), A = a, F = f: {result, F}. ALU group (00..3F excluded): the
  // operation is bits 5:3; 00 DDD 10x INR / DCR; 00 DDD 111 the
  // accumulator group.
  function [15:0] alu_ir;
    input [7:0] ir;
    input [7:0] b;
    input [7:0] a;
    input [7:0] f;
    reg   [4:0] op;
    begin
      op = {2'b00, ir[5:3]};
      if (ir[7:6] == 2'b00) begin
        case (ir[2:0])
          3'b100:  op = ALU_INR;
          3'b101:  op = ALU_DCR;
          default: op = ALU_RLC + {2'b00, ir[5:3]};  // RLC RRC RAL RAR DAA CMA STC CMC
        endcase
      end
      alu_ir = alu_exec(op, a, b, f);
    end
  endfunction

  // ------------------------------------------------------------ registers
  // All registers but the instruction register are written by one clocked
  // block, in three exclusive branches by where the T-state stands: inside
  // a cycle (the T-state count, the opcode at the end of T3 of a fetch,
  // the bus outputs at the end of T1), a cycle's last T-state (the
  // instruction's work and the next cycle), a unit's first T-state (the
  // pins decide what the unit is). Priority: reset, then a debug load,
  // then running (written last in the block).
  //
  // For the speed of a Verilated model: most T-states are inside a cycle
  // and run only that branch; and every register is read, in the block's
  // text, before it is written (what the pins decide, the next PC, the
  // work's results are computed into variables first and written after
  // the reads; the PC, the edge latches and the opcode's fetch length at
  // the end). A register written before a later read of it costs the
  // model a shadow copy at every clock.
  // The block's variables (and b) are not traced: a Verilated model keeps
  // a traced variable as a member and stores every default to it at every
  // clock; untraced, they are C++ locals that the compiler optimizes.
  // The decoder as a table: the class of every opcode, computed once (a
  // Verilated model reads one entry per instruction instead of evaluating
  // the decode; synthesis maps it to block RAM, read synchronously into
  // the class register at the end of the block).
  // The formal model decodes directly (the same function, untabulated:
  // yosys evaluates the table's 256 entries slowly).
`ifndef FORMAL
  reg [5:0] dec_rom [0:255];
  integer di;
  initial for (di = 0; di < 256; di = di + 1) dec_rom[di] = class_of(decode(di[7:0]));
`endif

  /* verilator tracing_off */
  integer b;
  always @(posedge i_clk) begin : cpu
    reg [ 2:0] irq, c, mc;
    reg [10:0] sq;                   // seq_next()
    reg [ 1:0] k;
    reg [15:0] pc_now;               // PC at a unit's first T-state
    reg        ie_now;               // IE at a unit's first T-state
    reg [ 3:0] of_v;                 // of_end() of the opcode read now
    reg        op_now;               // the opcode is read now
    reg        ack_now;              // a TRAP / RST x.5 acknowledge starts now
    reg        pc_we;                // o_dbg_pc <= pc_n at the end
    reg [15:0] pc_n;
    reg        trap_ack, r75_clr;   // the edge latches are cleared now
    reg        hlt_next;             // the unit that ends is followed by idle units
    reg        end_of, end_mc;       // the cycle that ends is the fetch / a later one
    reg        mc_1, mc_2, mc_3, mc_4;  // where the cycle index stands
    reg        sp_we;
    reg [15:0] sp_n;
    reg        w_we, z_we;
    reg [ 7:0] w_n, z_n;
    reg        rf_we, pair_we, f_we;
    reg        xchg;                 // XCHG swaps DE and HL now
    reg        ie_we, sim_now;       // DI / EI, SIM now
    reg [ 2:0] rf_wa;
    reg [ 7:0] rf_wd, f_wd;
    reg [ 1:0] pair_wa;
    reg [15:0] pair_wd, pair_v, alu_v;
    reg [16:0] dad_sum;
    reg [ 2:0] alu_src;
    /* verilator tracing_on */
    // Every variable has a value at every clock (else synthesis keeps one
    // read in a later part than the one that sets it in a flop), set here
    // at the top of the block, under no `if`: a Verilated model then makes
    // them C++ locals (it does so for a variable only if it is written
    // whole outside any branch before any read), which the compiler keeps
    // in registers and whose unused defaults it drops.
    {op_now, ack_now, pc_we, trap_ack, r75_clr} = 5'b00000;
    {irq, k, pc_now, ie_now, of_v, pc_n} = {IRQ_NONE, K_INSTR, 16'h0000, 1'b0, 4'h0, 16'h0000};
    {sp_we, sp_n, w_we, z_we, w_n, z_n} = {1'b0, 16'h0000, 2'b00, 8'h00, 8'h00};
    {rf_we, rf_wa, rf_wd, pair_we, pair_wa, pair_wd, f_we, f_wd} = {1'b0, 3'd0, 8'h00, 1'b0, 2'd0, 16'h0000, 1'b0, 8'h00};
    {c, sq, mc, hlt_next, end_of, end_mc, mc_1, mc_2, mc_3, mc_4} = {3'd0, 11'd0, 3'd0, 7'd0};
    {pair_v, alu_v, dad_sum, alu_src, xchg, ie_we, sim_now} = {16'h0000, 16'h0000, 17'h00000, 3'd0, 3'b000};
    b = 0;
    if (!i_rst && !i_dbg_load) begin
      // Bus strobes: one clock (T2); retire: the first T-state of a unit.
      {o_rd, o_wr, o_inta} <= 3'b000;
      o_retire <= 1'b0;
      if (unit_t1) begin
        // A unit's first T-state: what the pins decide (written below).
        irq = irq_decide(i_trap, i_rst75, i_rst65, i_rst55, i_intr);
        k = kind_of(irq);
        pc_now = o_dbg_pc;
        ie_now = o_ie;
      end
      if (!unit_t1 && o_tstate != len_q) begin
        // ---- A T-state inside a cycle.
        if (mc_q == 3'd0 && o_tstate == 3'd3 && (o_dbg_kind == K_INSTR || o_dbg_kind == K_INTR)) begin
          // The opcode (end of T3 of the fetch / INTA): the fetch's
          // length and whether the unit ends with it; PC + 1 past an
          // opcode read at PC (written at the end of the block).
          op_now = 1'b1;
          of_v = of_end(i_din);
          {pc_we, pc_n} = {o_dbg_kind == K_INSTR, o_dbg_pc + 16'd1};
        end
        if (o_tstate == 3'd1) begin
          // Bus: address, write data and strobes at the end of T1.
          o_addr <= addr_of(asel_q);
          o_dout <= dout_of(dsel_q);
          o_rd <= (o_cycle == CY_MR || o_cycle == CY_IOR);
          o_wr <= (o_cycle == CY_MW || o_cycle == CY_IOW);
          o_inta <= (o_cycle == CY_INA);
        end
        o_tstate <= o_tstate + 3'd1;
      end else if (!unit_t1) begin
        // ---- A cycle's last T-state.
        mc = mc_q + 3'd1;
        hlt_next = o_halted || (cix_q == C_HLT && mc_q == 3'd1);
        // The instruction's work, at the end of its cycles: of the
        // opcode fetch (end_of) or of a later cycle (end_mc); computed
        // here, written after the sequencer's registers below.
        end_of = (mc_q == 3'd0);
        end_mc = !end_of;
        {mc_1, mc_2, mc_3, mc_4} = {mc_q == 3'd1, mc_q == 3'd2, mc_q == 3'd3, mc_q == 3'd4};
        if (o_dbg_kind != K_IDLE) begin
          // The instruction's work at the end of a cycle, by class: one
          // case on the registered class index (a Verilated model
          // reaches the arm in a few bit tests and runs only its
          // statements; each arm tests the cycle index itself). Results
          // go to variables (PC, SP, W Z, the register file's three write
          // ports: one register rf_*, one pair B / D / H pair_*, the
          // flags f_*), written after the sequencer below; the interrupt
          // state (DI EI HLT RIM SIM) is written in its arm.
          //
          // Program counter, before the case: +1 for each operand byte
          // read at PC (not in an INTR acknowledge, whose operands come
          // by INTA cycles); the arms set jumps, calls, returns, RST, and
          // +2 over the address of a Jcc / Ccc not taken (not read; an
          // INTR acknowledge supplies no address to skip).
          if (end_mc && o_cycle == CY_MR && asel_q == A_PC) {pc_we, pc_n} = {1'b1, o_dbg_pc + 16'd1};
          case (cix_q)
            C_HLT: if (end_mc) o_halted <= 1'b1;  // its fifth T-state
            C_MOV_RR: {rf_we, rf_wa, rf_wd} = {1'b1, o_dbg_op[5:3], r8(o_dbg_op[2:0])};
            C_MOV_RM, C_MVI_R: if (end_mc) {rf_we, rf_wa, rf_wd} = {1'b1, o_dbg_op[5:3], i_din};
            C_ALU_R, C_INCDEC_R, C_ACC: begin
              // ALU r, INR / DCR r, the accumulator group: at the end of
              // the fetch. The operand: SSS for ALU r, DDD otherwise (6:
              // STC, whose operand is unused).
              alu_src = (o_dbg_op[7:6] == 2'b00) ? o_dbg_op[5:3] : o_dbg_op[2:0];
              alu_v = alu_ir(o_dbg_op, (alu_src == 3'd6) ? i_din : r8(alu_src), r8(R_A), r8(R_F));
              // CMP writes only F; INR / DCR r their register.
              {rf_we, rf_wa, rf_wd} = {(cix_q != C_ALU_R) || (o_dbg_op[5:3] != 3'd7), (cix_q == C_INCDEC_R) ? o_dbg_op[5:3] : R_A, alu_v[15:8]};
              {f_we, f_wd} = {1'b1, alu_v[7:0]};
            end
            C_ALU_M, C_ALU_I: if (end_mc) begin
              alu_v = alu_ir(o_dbg_op, i_din, r8(R_A), r8(R_F));
              {rf_we, rf_wa, rf_wd} = {o_dbg_op[5:3] != 3'd7, R_A, alu_v[15:8]};
              {f_we, f_wd} = {1'b1, alu_v[7:0]};
            end
            C_MVI_M: if (mc_1) {z_we, z_n} = {1'b1, i_din};
            C_INCDEC_M: if (mc_1) begin  // INR / DCR M: the result to Z, written by the MW
              alu_v = alu_ir(o_dbg_op, i_din, r8(R_A), r8(R_F));
              {z_we, z_n} = {1'b1, alu_v[15:8]};
              {f_we, f_wd} = {1'b1, alu_v[7:0]};
            end
            C_LXI: begin
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_2 && o_dbg_op[5:4] != 2'd3) {pair_we, pair_wa, pair_wd} = {1'b1, o_dbg_op[5:4], i_din, z_q};
              if (mc_2 && o_dbg_op[5:4] == 2'd3) {sp_we, sp_n} = {1'b1, i_din, z_q};
            end
            C_DAD: if (mc_2) begin
              pair_v = (o_dbg_op[5:4] == 2'd0) ? {r8(R_B), r8(R_C)} : (o_dbg_op[5:4] == 2'd1) ? {r8(R_D), r8(R_E)} :
                       (o_dbg_op[5:4] == 2'd2) ? {r8(R_H), r8(R_L)} : o_dbg_sp;
              dad_sum = {1'b0, {r8(R_H), r8(R_L)}} + {1'b0, pair_v};
              {pair_we, pair_wa, pair_wd} = {1'b1, 2'd2, dad_sum[15:0]};
              {f_we, f_wd} = {1'b1, o_dbg_regs[RF_F + 7:RF_F + 1], dad_sum[16]};
            end
            C_INX, C_DCX: begin
              // Stack pointer: SP for rp 3, a pair otherwise.
              pair_v = (o_dbg_op[5:4] == 2'd0) ? {r8(R_B), r8(R_C)} : (o_dbg_op[5:4] == 2'd1) ? {r8(R_D), r8(R_E)} :
                       (o_dbg_op[5:4] == 2'd2) ? {r8(R_H), r8(R_L)} : o_dbg_sp;
              pair_v = (cix_q == C_INX) ? pair_v + 16'd1 : pair_v - 16'd1;
              if (o_dbg_op[5:4] == 2'd3) {sp_we, sp_n} = {1'b1, pair_v};
              else {pair_we, pair_wa, pair_wd} = {1'b1, o_dbg_op[5:4], pair_v};
            end
            C_LDAX: if (end_mc) {rf_we, rf_wa, rf_wd} = {1'b1, R_A, i_din};
            C_DIRECT: begin  // SHLD LHLD STA LDA: address Z W, then the data
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_2) {w_we, w_n} = {1'b1, i_din};
              if (mc_3 && o_dbg_op[3]) {rf_we, rf_wa, rf_wd} = {1'b1, o_dbg_op[4] ? R_A : R_L, i_din};
              if (mc_3 && !o_dbg_op[4]) {w_we, z_we, w_n, z_n} = {2'b11, {w_q, z_q} + 16'd1};
              if (mc_4 && o_dbg_op[3]) {rf_we, rf_wa, rf_wd} = {1'b1, R_H, i_din};
            end
            C_RIM: begin  // RIM; it ends the after-TRAP IE
              {rf_we, rf_wa, rf_wd} = {1'b1, R_A, i_sid, r75_latch_q | (i_rst75 & ~r75_prev_q), i_rst65, i_rst55,
                                       rim_after_trap_q ? ie_before_trap_q : o_ie, masks_q};
              rim_after_trap_q <= 1'b0;
            end
            C_SIM: begin  // the masks (with MSE), SOD (with SOE): below; R7.5 clears the latch
              sim_now = 1'b1;
              r75_clr = o_dbg_regs[RF_A + 4];
            end
            C_RCC, C_RET, C_POP: if (end_mc) begin  // pops increment SP after each read
              {sp_we, sp_n} = {1'b1, o_dbg_sp + 16'd1};
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_2 && cix_q != C_POP) {pc_we, pc_n} = {1'b1, i_din, z_q};
              if (mc_2 && cix_q == C_POP && o_dbg_op[5:4] != 2'd3) {pair_we, pair_wa, pair_wd} = {1'b1, o_dbg_op[5:4], i_din, z_q};
              if (mc_2 && cix_q == C_POP && o_dbg_op[5:4] == 2'd3) begin
                {rf_we, rf_wa, rf_wd} = {1'b1, R_A, i_din};
                {f_we, f_wd} = {1'b1, z_q & 8'hD5};
              end
            end
            C_JCC, C_JMP, C_OUT, C_IN: begin
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_1 && cix_q == C_JCC && !cond_ir(o_dbg_op[5:3]) && o_dbg_kind != K_INTR) {pc_we, pc_n} = {1'b1, o_dbg_pc + 16'd2};
              if (mc_2 && (cix_q == C_JCC || cix_q == C_JMP)) {pc_we, pc_n} = {1'b1, i_din, z_q};
              if (mc_2 && cix_q == C_IN) {rf_we, rf_wa, rf_wd} = {1'b1, R_A, i_din};
            end
            C_XTHL: begin  // (SP) to Z, (SP+1) to W, H and L written, then W Z to HL
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_2) {w_we, w_n} = {1'b1, i_din};
              if (mc_4) {pair_we, pair_wa, pair_wd} = {1'b1, 2'd2, {w_q, z_q}};
            end
            C_XCHG: xchg = 1'b1;
            C_PCHL: {pc_we, pc_n} = {1'b1, r8(R_H), r8(R_L)};
            C_SPHL: {sp_we, sp_n} = {1'b1, r8(R_H), r8(R_L)};
            C_DI, C_EI: ie_we = 1'b1;  // at the end of the fetch; EI with its one-unit shadow (below)
            C_CCC, C_CALL: begin  // address Z W; pushes decrement SP before each write
              if (mc_1) {z_we, z_n} = {1'b1, i_din};
              if (mc_1 && cix_q == C_CCC && !cond_ir(o_dbg_op[5:3]) && o_dbg_kind != K_INTR) {pc_we, pc_n} = {1'b1, o_dbg_pc + 16'd2};
              if (mc_2) {w_we, w_n} = {1'b1, i_din};
              if (mc_2 || mc_3) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
              if (mc_4) {pc_we, pc_n} = {1'b1, w_q, z_q};
            end
            C_PUSH, C_RST: begin
              if (end_of || mc_1) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
              if (mc_2 && cix_q == C_RST) {pc_we, pc_n} = {1'b1, (o_dbg_kind == K_IACK) ? vec_q : {10'b0, o_dbg_op[5:3], 3'b000}};
            end
            C_MOV_MR, C_STAX, C_NOP: ;  // no work but the bus's
            default: ;  // (no class)
          endcase
`ifdef FORMAL
          // The byte and pair write ports never address F (index 6, pair 3).
          assert (!rf_we || rf_wa != R_F);
          assert (!pair_we || pair_wa != 2'd3);
`endif
        end
        // Sequencer: the unit ends (the next one starts as an opcode
        // fetch, or as an idle T-state while halted, until its first
        // T-state decides), or its next cycle starts: its description
        // is registered once, here.
        o_tstate <= 3'd1;
        if (last_q) begin
          unit_t1 <= 1'b1;
          o_retire <= 1'b1;
          o_cycle <= hlt_next ? CY_HLT : CY_OF;
          {asel_q, dsel_q, o_io} <= {A_PC, D_A, 1'b0};
          mc_q <= 3'd0;
        end else begin
          // (One variable: Verilator splits an assignment to a
          // concatenation into one per part, each calling the function.)
          sq = seq_next(mc);
          c = sq[10:8];
          {o_cycle, asel_q, dsel_q, last_q} <= sq;
          len_q <= (c == CY_HLT) ? 3'd1 : 3'd3;
          o_io <= (c == CY_IOR || c == CY_IOW);
          // A 1-T cycle (HLT's fifth T-state) has no T2.
          mc_q <= mc;
        end
        if (o_dbg_kind != K_IDLE) begin
          // The work's results. DI / EI, SIM: written here, after RIM's
          // read of IE and the masks in the case above (a register written
          // before a later read costs a Verilated model a shadow copy).
          if (ie_we) {o_ie, ei_delay_q} <= {2{cix_q == C_EI}};
          if (sim_now) begin
            if (o_dbg_regs[RF_A + 3]) masks_q <= o_dbg_regs[RF_A + 2:RF_A + 0];
            if (o_dbg_regs[RF_A + 6]) o_sod <= o_dbg_regs[RF_A + 7];
          end
          if (sp_we) o_dbg_sp <= sp_n;
          if (w_we) w_q <= w_n;
          if (z_we) z_q <= z_n;
          // F is written by its own port only: the byte and pair ports
          // never address it (asserted above), the guards tell synthesis
          // so. One enable per byte and per pair (what the register
          // file's address decode was as an array; the register file
          // keeps its shadow copy in a Verilated model: a partial write).
          // (Each port under its enable: a Verilated model tests one
          // enable, not each byte, at the end of a cycle that does not
          // write.)
          if (rf_we)
            for (b = 0; b < 8; b = b + 1)
              if (rf_wa != R_F && rf_pos(rf_wa) == b[2:0]) o_dbg_regs[8*b +: 8] <= rf_wd;
          if (pair_we)
            for (b = 0; b < 3; b = b + 1)  // BC at bits 47:32, DE 31:16, HL 15:0
              if (pair_wa == b[1:0]) o_dbg_regs[16*(2-b) +: 16] <= pair_wd;
          if (f_we) o_dbg_regs[RF_F + 7:RF_F] <= f_wd;
          if (xchg) o_dbg_regs[31:0] <= {o_dbg_regs[15:0], o_dbg_regs[31:16]};  // DE <-> HL
        end
      end
      if (unit_t1) begin
        // ---- A unit's first T-state: an idle unit ends here, anything
        // else starts its first cycle; its opcode (end of T3) gives the
        // fetch's length.
        if (k == K_IDLE) begin
          o_retire <= 1'b1;
          o_cycle <= CY_HLT;
        end else begin
          unit_t1 <= 1'b0;
          o_tstate <= 3'd2;
          c = (k == K_IACK) ? CY_BI : (k == K_INTR) ? CY_INA : CY_OF;
          {o_cycle, asel_q, dsel_q, o_io} <= {c, A_PC, D_A, 1'b0};
          // Until the opcode is read, an instruction's fetch is 4 T long.
          {len_q, last_q} <= (k == K_IACK) ? {3'd6, 1'b0} : {3'd4, 1'b1};
          ack_now = (k == K_IACK);
          o_rd <= (c == CY_OF);
          o_inta <= (c == CY_INA);
          o_addr <= pc_now;
        end
        // Unit kind, interrupt, PC at its start, the vector of a TRAP /
        // RST x.5 acknowledge.
        o_dbg_kind <= k;
        o_dbg_irq <= irq;
        o_dbg_ipc <= pc_now;
        case (irq)
          IRQ_TRAP: vec_q <= 16'h0024;
          IRQ_75: vec_q <= 16'h003C;
          IRQ_65: vec_q <= 16'h0034;
          default: vec_q <= 16'h002C;
        endcase
        // An acknowledge clears its edge latch (at the end), IE and
        // halted; the EI shadow lasts one unit; RIM's IE bit after a
        // TRAP: IE as it was before the TRAP, until the first RIM.
        trap_ack = (irq == IRQ_TRAP);
        r75_clr = (irq == IRQ_75);
        ei_delay_q <= 1'b0;
        if (irq != IRQ_NONE) begin
          o_ie <= 1'b0;
          o_halted <= 1'b0;
        end
        if (irq == IRQ_TRAP) begin
          ie_before_trap_q <= ie_now;
          rim_after_trap_q <= 1'b1;
        end
      end
      // The opcode's fetch length and end, the PC.
      if (op_now) {len_q, last_q} <= of_v;
      if (pc_we) o_dbg_pc <= pc_n;
      // TRAP and RST 7.5 edge latches: set by a rising edge of their pin
      // at any time, cleared by their acknowledge (and RST 7.5's by SIM
      // with R7.5); the clearing wins (written last). Each pin is tested
      // for a change first: one test per pin at a clock where it does not
      // change (a Verilated model runs these at every clock).
      if (i_trap != trap_prev_q) begin
        trap_prev_q <= i_trap;
        if (i_trap) trap_latch_q <= 1'b1;
      end
      if (i_rst75 != r75_prev_q) begin
        r75_prev_q <= i_rst75;
        if (i_rst75) r75_latch_q <= 1'b1;
      end
      if (trap_ack) trap_latch_q <= 1'b0;
      if (r75_clr) r75_latch_q <= 1'b0;
    end
    // Reset and a debug load: after the running part (whose reads of the
    // registers then all precede their writes).
    if (i_rst) begin
      // Sequencer and bus.
      o_tstate <= 3'd1;
      mc_q <= 3'd0;
      unit_t1 <= 1'b1;
      o_retire <= 1'b0;
      {o_cycle, asel_q, dsel_q, len_q, last_q} <= {CY_OF, A_PC, D_A, 3'd4, 1'b1};
      {o_rd, o_wr, o_io, o_inta} <= 4'b0000;
      o_addr <= 16'h0000;
      o_dout <= 8'h00;
      // Unit kind.
      o_dbg_kind <= K_INSTR;
      o_dbg_irq <= IRQ_NONE;
      o_dbg_ipc <= 16'h0000;
      vec_q <= 16'h0000;
      // Edge latches, interrupt state, SIM.
      trap_prev_q <= 1'b0;
      r75_prev_q <= 1'b0;
      trap_latch_q <= 1'b0;
      r75_latch_q <= 1'b0;
      o_ie <= 1'b0;
      ei_delay_q <= 1'b0;
      o_halted <= 1'b0;
      rim_after_trap_q <= 1'b0;
      ie_before_trap_q <= 1'b0;
      masks_q <= 3'b111;
      o_sod <= 1'b0;
      // PC, SP, register file, W Z.
      o_dbg_pc <= 16'h0000;
      o_dbg_sp <= 16'h0000;
      o_dbg_regs <= 64'h0;
      w_q <= 8'h00;
      z_q <= 8'h00;
    end else if (i_dbg_load) begin
      o_dbg_pc <= i_dbg_pc;
      o_dbg_sp <= i_dbg_sp;
      o_dbg_regs <= i_dbg_regs;
    end
    // Instruction register and its class (the table above),
    // written last (every read of them in the block precedes): the
    // opcode at the end of T3 of the fetch / INTA; a TRAP / RST x.5
    // acknowledge runs as RST 7 (FF), loaded at the end of its first
    // T-state (nothing reads the class before its first cycle ends);
    // 00 at reset. One read of the table.
    if (i_rst || op_now || ack_now) begin
`ifndef FORMAL
      cix_q <= dec_rom[i_rst ? 8'h00 : op_now ? i_din : 8'hFF];
`else
      cix_q <= class_of(decode(i_rst ? 8'h00 : op_now ? i_din : 8'hFF));
`endif
      o_dbg_op <= i_rst ? 8'h00 : op_now ? i_din : 8'hFF;
    end
  end


`ifdef FORMAL
  // ------------------------------------------------------------- formal
  // Proved by rtl/cpu8085/formal/prove.sh from reset, for any pins and bus
  // data. Debug loads are assumed at unit boundaries only (their documented
  // use: a load mid-instruction may change F under a pending condition).
  reg f_past_valid = 1'b0;
  always @(posedge i_clk) f_past_valid <= 1'b1;
  always @* begin
    if (!f_past_valid) assume (i_rst);
    if (i_dbg_load) assume (unit_t1);
  end
  // The classes of the registered opcode, and the registered class.
  wire [39:0] classes = decode(o_dbg_op);
  wire is_hlt = (cix_q == C_HLT), is_mov_mr = (cix_q == C_MOV_MR), is_mov_rm = (cix_q == C_MOV_RM);
  wire is_alu_m = (cix_q == C_ALU_M), is_alu_i = (cix_q == C_ALU_I), is_mvi_r = (cix_q == C_MVI_R);
  wire is_mvi_m = (cix_q == C_MVI_M), is_incdec_m = (cix_q == C_INCDEC_M), is_lxi = (cix_q == C_LXI);
  wire is_dad = (cix_q == C_DAD), is_inx = (cix_q == C_INX), is_dcx = (cix_q == C_DCX);
  wire is_stax = (cix_q == C_STAX), is_ldax = (cix_q == C_LDAX), is_direct = (cix_q == C_DIRECT);
  wire is_rcc = (cix_q == C_RCC), is_ret = (cix_q == C_RET), is_pop = (cix_q == C_POP);
  wire is_jcc = (cix_q == C_JCC), is_jmp = (cix_q == C_JMP), is_out = (cix_q == C_OUT);
  wire is_in = (cix_q == C_IN), is_xthl = (cix_q == C_XTHL), is_pchl = (cix_q == C_PCHL);
  wire is_sphl = (cix_q == C_SPHL), is_ccc = (cix_q == C_CCC), is_call = (cix_q == C_CALL);
  wire is_push = (cix_q == C_PUSH), is_rst = (cix_q == C_RST);
  // The 39 classes of decode_all (NOP included) are one-hot.
  function f_onehot;
    input [42:0] all;
    begin
      f_onehot = (all[42:4] != 39'd0) && ((all[42:4] & (all[42:4] - 39'd1)) == 39'd0);
    end
  endfunction
  // A clock in which the CPU runs (neither reset nor a debug load).
  wire f_run = f_past_valid && !i_rst && !i_dbg_load;

  // The unit ends with this T-state.
  wire f_unit_end = unit_t1 ? (kind_of(irq_decide(i_trap, i_rst75, i_rst65, i_rst55, i_intr)) == K_IDLE)
                            : ((o_tstate == len_q) && last_q);
  // unit_t1 is the first T-state of a unit.
  always @* if (f_past_valid) assert (unit_t1 == (mc_q == 3'd0 && o_tstate == 3'd1));
  // T-states of the current unit before this one.
  reg [4:0] f_t_q;
  always @(posedge i_clk) begin
    if (i_rst) f_t_q <= 5'd0;
    else if (!i_dbg_load) f_t_q <= f_unit_end ? 5'd0 : f_t_q + 5'd1;
  end

  // The data sheet's T-states of the instruction in o_dbg_op (its condition as
  // it stands: no conditional instruction changes F).
  reg [4:0] f_t_expect;
  always @* begin
    f_t_expect = 5'd4;  // MOV r,r, ALU r, INR / DCR r, rotates, NOP, ...
    if (is_hlt) f_t_expect = 5'd5;
    if (is_inx | is_dcx | is_pchl | is_sphl) f_t_expect = 5'd6;
    if (is_mov_mr | is_mov_rm | is_alu_m | is_alu_i | is_mvi_r) f_t_expect = 5'd7;
    if (is_stax | is_ldax) f_t_expect = 5'd7;
    if (is_mvi_m | is_incdec_m | is_lxi | is_dad | is_ret | is_pop | is_jmp) f_t_expect = 5'd10;
    if (is_out | is_in) f_t_expect = 5'd10;
    if (is_push | is_rst) f_t_expect = 5'd12;
    if (is_direct) f_t_expect = o_dbg_op[4] ? 5'd13 : 5'd16;  // STA LDA / SHLD LHLD
    if (is_xthl) f_t_expect = 5'd16;
    if (is_call) f_t_expect = 5'd18;
    if (is_rcc) f_t_expect = cond_ir(o_dbg_op[5:3]) ? 5'd12 : 5'd6;
    if (is_jcc) f_t_expect = cond_ir(o_dbg_op[5:3]) ? 5'd10 : 5'd7;
    if (is_ccc) f_t_expect = cond_ir(o_dbg_op[5:3]) ? 5'd18 : 5'd9;
  end

  always @* begin
    if (f_past_valid) begin
      // The registered classes are the decode of o_dbg_op, one-hot.
      assert (cix_q == class_of(classes));
      assert (f_onehot(decode_all(o_dbg_op)));
      // The sequencer stays in range: T1..T6 in an opcode fetch / BI6,
      // T1..T3 in later cycles, at most five cycles per unit.
      assert (o_tstate >= 3'd1 && o_tstate <= 3'd6);
      assert (mc_q <= 3'd4);
      if (mc_q != 3'd0) assert (o_tstate <= 3'd3);
      assert (o_dbg_kind != K_IDLE || mc_q == 3'd0);
    end
    if (f_run) begin
      // At most one bus strobe.
      assert ({1'b0, o_rd} + {1'b0, o_wr} + {1'b0, o_inta} <= 2'd1);
      // A unit ends after the data sheet's number of T-states: an
      // instruction (also one supplied by INTA) by its class, a TRAP /
      // RST x.5 acknowledge 12, an idle unit 1.
      if (f_unit_end && unit_t1) assert (f_t_q == 5'd0);
      if (f_unit_end && !unit_t1) begin
        // begin/end: `assert (...); else` would bind the else to the
        // assert (its fail action) in SystemVerilog.
        if (o_dbg_kind == K_IACK) begin
          assert (f_t_q + 5'd1 == 5'd12);
        end else begin
          assert (f_t_q + 5'd1 == f_t_expect);
        end
      end
    end
  end
`endif

  // ---------------------------------------------------------------- debug
endmodule

`default_nettype wire
