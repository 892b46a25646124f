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

  wire [2:0] ddd = o_dbg_op[5:3];
  wire [2:0] sss = o_dbg_op[2:0];
  wire [1:0] rp = o_dbg_op[5:4];

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
  // The opcode decoded into one-hot classes (cpu8085_decode.vh), registered
  // with the instruction register: once per instruction.
`include "cpu8085_decode.vh"
  reg [39:0] cls_q;  // decode()'s classes, in its order
  wire is_hlt, is_mov_rr, is_mov_mr, is_mov_rm, is_alu_r, is_alu_m, is_alu_i;
  wire is_mvi_r, is_mvi_m, is_incdec_r, is_incdec_m, is_acc;
  wire is_lxi, is_dad, is_inx, is_dcx, is_stax, is_ldax, is_direct;
  wire is_rim, is_sim, is_rcc, is_ret, is_pop, is_jcc, is_jmp;
  wire is_out, is_in, is_xthl, is_xchg, is_pchl, is_sphl, is_di, is_ei;
  wire is_ccc, is_call, is_push, is_rst;
  // Classes that share their cycle list.
  wire is_mem_rmw;  // MVI M, INR / DCR M: MR (or operand) then MW (HL)
  wire is_pop_ret;  // Rcc RET POP: two reads at SP
  assign {is_hlt, is_mov_rr, is_mov_mr, is_mov_rm, is_alu_r, is_alu_m, is_alu_i,
          is_mvi_r, is_mvi_m, is_incdec_r, is_incdec_m, is_acc,
          is_lxi, is_dad, is_inx, is_dcx, is_stax, is_ldax, is_direct,
          is_rim, is_sim, is_rcc, is_ret, is_pop, is_jcc, is_jmp,
          is_out, is_in, is_xthl, is_xchg, is_pchl, is_sphl, is_di, is_ei,
          is_ccc, is_call, is_push, is_rst,
          is_mem_rmw, is_pop_ret} = cls_q;

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
  // unit: its type (seq_cyc), address (seq_asel) and write data (seq_dsel)
  // sources, and whether it is the unit's last cycle (seq_last); the data
  // sheet's cycle list of each class. The sequencer registers them when the
  // cycle starts (o_cycle, asel_q, dsel_q, last_q): they are computed once
  // per cycle, not at every clock. Each function assigns its default
  // first; the class flags are one-hot, so at most one of the `if`s after
  // it applies and their order is immaterial.
  // Write data sources.
  localparam [3:0] D_A = 4'd0, D_SSS = 4'd1, D_Z = 4'd2, D_L = 4'd3, D_H = 4'd4;
  localparam [3:0] D_PCH = 4'd5, D_PCL = 4'd6, D_PUSH_HI = 4'd7, D_PUSH_LO = 4'd8;

  // Address source.
  function [2:0] seq_asel;
    input [2:0] mc;
    begin
      seq_asel = A_PC;
      if (is_mov_mr | is_mov_rm | is_alu_m) seq_asel = A_HL;
      if (is_mem_rmw) seq_asel = (is_mvi_m && mc == 3'd1) ? A_PC : A_HL;
      if (is_stax | is_ldax) seq_asel = o_dbg_op[4] ? A_DE : A_BC;
      if (is_direct) seq_asel = (mc <= 3'd2) ? A_PC : A_WZ;
      if (is_pop_ret | is_push | is_rst) seq_asel = A_SP;
      if (is_out | is_in) seq_asel = (mc == 3'd1) ? A_PC : A_ZZ;
      if (is_xthl) seq_asel = (mc == 3'd1 || mc == 3'd4) ? A_SP : A_SP1;  // H to SP+1 first
      if (is_ccc | is_call) seq_asel = (mc <= 3'd2) ? A_PC : A_SP;
    end
  endfunction

  // Cycle type, given the cycle's address source asel (seq_asel(mc)). An
  // INTR acknowledge reads its operand bytes by INTA cycles.
  function [2:0] seq_cyc;
    input [2:0] mc;
    input [2:0] asel;
    reg at_1, at_le2;
    begin
      at_1 = (mc == 3'd1);
      at_le2 = (mc <= 3'd2);
      seq_cyc = CY_MR;
      if (is_hlt) seq_cyc = CY_HLT;  // its fifth T-state
      if (is_mov_mr | is_stax | is_push | is_rst) seq_cyc = CY_MW;
      if (is_mem_rmw) seq_cyc = at_1 ? CY_MR : CY_MW;
      if (is_dad) seq_cyc = CY_BI;  // two bus idle cycles
      if (is_direct) seq_cyc = (at_le2 || o_dbg_op[3]) ? CY_MR : CY_MW;
      if (is_out | is_in) seq_cyc = at_1 ? CY_MR : (is_in ? CY_IOR : CY_IOW);
      if (is_xthl | (is_ccc | is_call)) seq_cyc = at_le2 ? CY_MR : CY_MW;
      if (o_dbg_kind == K_INTR && seq_cyc == CY_MR && asel == A_PC) seq_cyc = CY_INA;
    end
  endfunction

  // Write data source.
  function [3:0] seq_dsel;
    input [2:0] mc;
    begin
      seq_dsel = D_A;
      if (is_mov_mr) seq_dsel = D_SSS;
      if (is_mem_rmw) seq_dsel = D_Z;
      if (is_direct) seq_dsel = o_dbg_op[4] ? D_A : (mc == 3'd3) ? D_L : D_H;
      if (is_xthl) seq_dsel = (mc == 3'd3) ? D_H : D_L;
      if (is_ccc | is_call) seq_dsel = (mc == 3'd3) ? D_PCH : D_PCL;
      if (is_rst) seq_dsel = (mc == 3'd1) ? D_PCH : D_PCL;
      if (is_push) seq_dsel = (mc == 3'd1) ? D_PUSH_HI : D_PUSH_LO;
    end
  endfunction

  // Last cycle of the unit: Jcc / Ccc end after their first operand byte
  // when the condition fails.
  function seq_last;
    input [2:0] mc;
    reg at_1, at_2, at_3, at_4;
    begin
      {at_1, at_2, at_3, at_4} = {mc == 3'd1, mc == 3'd2, mc == 3'd3, mc == 3'd4};
      seq_last = 1'b1;
      if (is_mem_rmw | is_lxi | is_dad | is_pop_ret | is_jmp | (is_out | is_in)) seq_last = at_2;
      if (is_push | is_rst) seq_last = at_2;
      if (is_jcc) seq_last = at_2 || !cond_ir(ddd);
      if (is_direct) seq_last = o_dbg_op[4] ? at_3 : at_4;
      if (is_xthl) seq_last = at_4;
      if (is_ccc | is_call) seq_last = at_4 || (at_1 && is_ccc && !cond_ir(ddd));
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
        D_SSS: dout_of = r8(sss);
        D_Z: dout_of = z_q;
        D_L: dout_of = r8(R_L);
        D_H: dout_of = r8(R_H);
        D_PCH: dout_of = o_dbg_pc[15:8];
        D_PCL: dout_of = o_dbg_pc[7:0];
        D_PUSH_HI: dout_of = (rp == 2'd3) ? r8(R_A) : r8({rp, 1'b0});
        D_PUSH_LO: dout_of = (rp == 2'd3) ? r8(R_F) : r8({rp, 1'b1});
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
  /* verilator tracing_off */
  integer b;
  always @(posedge i_clk) begin : cpu
    reg [ 2:0] irq, a, c, mc;
    reg [ 1:0] k;
    reg [15:0] pc_now;               // PC at a unit's first T-state
    reg        ie_now;               // IE at a unit's first T-state
    reg [ 3:0] of_v;                 // of_end() of the opcode read now
    reg        op_now;               // the opcode is read now
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
    {op_now, pc_we, trap_ack, r75_clr} = 4'b0000;
    {irq, k, pc_now, ie_now, of_v, pc_n} = {IRQ_NONE, K_INSTR, 16'h0000, 1'b0, 4'h0, 16'h0000};
    {sp_we, sp_n, w_we, z_we, w_n, z_n} = {1'b0, 16'h0000, 2'b00, 8'h00, 8'h00};
    {rf_we, rf_wa, rf_wd, pair_we, pair_wa, pair_wd, f_we, f_wd} = {1'b0, 3'd0, 8'h00, 1'b0, 2'd0, 16'h0000, 1'b0, 8'h00};
    {a, c, mc, hlt_next, end_of, end_mc, mc_1, mc_2, mc_3, mc_4} = {3'd0, 3'd0, 3'd0, 7'd0};
    {pair_v, alu_v, dad_sum, alu_src} = {16'h0000, 16'h0000, 17'h00000, 3'd0};
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
        hlt_next = o_halted || (is_hlt && mc_q == 3'd1);
        // The instruction's work, at the end of its cycles: of the
        // opcode fetch (end_of) or of a later cycle (end_mc); computed
        // here, written after the sequencer's registers below.
        end_of = (mc_q == 3'd0);
        end_mc = !end_of;
        {mc_1, mc_2, mc_3, mc_4} = {mc_q == 3'd1, mc_q == 3'd2, mc_q == 3'd3, mc_q == 3'd4};
        if (o_dbg_kind != K_IDLE) begin
          // Program counter: +1 for each operand byte read at PC; +2
          // over the address of a Jcc / Ccc not taken (not read; an INTR
          // acknowledge supplies no address to skip); jumps, calls,
          // returns, RST.
          if (end_of && is_pchl) {pc_we, pc_n} = {1'b1, r8(R_H), r8(R_L)};
          if (end_mc) begin
            if (o_cycle == CY_MR && asel_q == A_PC) {pc_we, pc_n} = {1'b1, o_dbg_pc + 16'd1};
            if (mc_1 && (is_jcc | is_ccc) && !cond_ir(ddd) && o_dbg_kind != K_INTR) {pc_we, pc_n} = {1'b1, o_dbg_pc + 16'd2};
            if (mc_2 && (is_jcc | is_jmp | is_rcc | is_ret)) {pc_we, pc_n} = {1'b1, i_din, z_q};
            if (mc_4 && (is_ccc | is_call)) {pc_we, pc_n} = {1'b1, w_q, z_q};
            if (mc_2 && is_rst) {pc_we, pc_n} = {1'b1, (o_dbg_kind == K_IACK) ? vec_q : {10'b0, ddd, 3'b000}};
          end
          // Stack pointer: pushes decrement before each write, pops
          // increment after each read; SPHL, LXI SP, INX SP, DCX SP.
          {sp_we, sp_n} = {1'b0, o_dbg_sp};
          if (end_of && (is_push | is_rst)) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
          if (end_of && is_sphl) {sp_we, sp_n} = {1'b1, r8(R_H), r8(R_L)};
          if (end_of && is_inx && rp == 2'd3) {sp_we, sp_n} = {1'b1, o_dbg_sp + 16'd1};
          if (end_of && is_dcx && rp == 2'd3) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
          if (end_mc) begin
            if (mc_2 && is_lxi && rp == 2'd3) {sp_we, sp_n} = {1'b1, i_din, z_q};
            if (is_pop_ret) {sp_we, sp_n} = {1'b1, o_dbg_sp + 16'd1};
            if ((mc_2 || mc_3) && (is_ccc | is_call)) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
            if (mc_1 && (is_push | is_rst)) {sp_we, sp_n} = {1'b1, o_dbg_sp - 16'd1};
          end
          // SIM with R7.5 clears the RST 7.5 latch (at the end).
          r75_clr = end_of && is_sim && o_dbg_regs[RF_A + 4];
          // Register file B C D E H L F A, through three write ports
          // decoded from the class: one register (rf_we: MOV, MVI, INR r
          // / DCR r, accumulator results, loads), one pair B / D / H
          // (pair_we: LXI, INX, DCX, DAD, POP but PSW, XTHL), the flags
          // (f_we: ALU results, DAD's carry, POP PSW), and XCHG's swap of
          // DE and HL; the temporary pair W Z (operand bytes, Z first;
          // INR M / DCR M's result; SHLD / LHLD's address + 1). The ports
          // and the ALU are computed only when a cycle ends.
          // The ALU's register operand: DDD for INR / DCR, SSS otherwise (6:
          // M, the byte read).
          alu_src = (o_dbg_op[7:6] == 2'b00) ? ddd : sss;
          // The ALU only for the classes whose result it is (a Verilated model
          // skips it at the end of other cycles; its value is unused there).
          alu_v = 16'h0000;
          if (is_alu_r | is_alu_m | is_alu_i | is_incdec_r | is_incdec_m | is_acc)
            alu_v = alu_ir(o_dbg_op, (alu_src == 3'd6) ? i_din : r8(alu_src), r8(R_A), r8(R_F));
          pair_v = (rp == 2'd0) ? {r8(R_B), r8(R_C)} : (rp == 2'd1) ? {r8(R_D), r8(R_E)} : {r8(R_H), r8(R_L)};  // rp 3 (SP): not here
          dad_sum = {1'b0, {r8(R_H), r8(R_L)}} + {1'b0, (rp == 2'd3) ? o_dbg_sp : pair_v};
          {rf_we, rf_wa, rf_wd} = {1'b0, R_A, alu_v[15:8]};
          {pair_we, pair_wa, pair_wd} = {1'b0, rp, i_din, z_q};
          {f_we, f_wd} = {1'b0, alu_v[7:0]};
          {w_we, z_we, w_n, z_n} = {2'b00, w_q, z_q};
          if (end_of) begin
            if (is_mov_rr) {rf_we, rf_wa, rf_wd} = {1'b1, ddd, r8(sss)};
            if (is_alu_r) rf_we = (ddd != 3'd7);  // CMP writes only F
            if (is_incdec_r) {rf_we, rf_wa} = {1'b1, ddd};
            if (is_acc) rf_we = 1'b1;
            if (is_rim)
              {rf_we, rf_wd} = {1'b1, i_sid, r75_latch_q | (i_rst75 & ~r75_prev_q), i_rst65, i_rst55,
                                rim_after_trap_q ? ie_before_trap_q : o_ie, masks_q};
            if (is_inx && rp != 2'd3) {pair_we, pair_wd} = {1'b1, pair_v + 16'd1};
            if (is_dcx && rp != 2'd3) {pair_we, pair_wd} = {1'b1, pair_v - 16'd1};
            if (is_alu_r | is_incdec_r | is_acc) f_we = 1'b1;
          end else begin
            if (is_mov_rm || is_mvi_r) {rf_we, rf_wa, rf_wd} = {1'b1, ddd, i_din};
            if (is_alu_m || is_alu_i) rf_we = (ddd != 3'd7);
            if (is_ldax || (is_in && mc_2)) {rf_we, rf_wd} = {1'b1, i_din};
            if (is_direct && mc_3 && o_dbg_op[3]) {rf_we, rf_wa, rf_wd} = {1'b1, o_dbg_op[4] ? R_A : R_L, i_din};
            if (is_direct && mc_4 && o_dbg_op[3]) {rf_we, rf_wa, rf_wd} = {1'b1, R_H, i_din};
            if (is_pop && mc_2 && rp == 2'd3) {rf_we, rf_wd} = {1'b1, i_din};
            if (mc_2 && rp != 2'd3 && (is_lxi || is_pop)) pair_we = 1'b1;
            if (mc_2 && is_dad) {pair_we, pair_wa, pair_wd} = {1'b1, 2'd2, dad_sum[15:0]};
            if (mc_4 && is_xthl) {pair_we, pair_wa, pair_wd} = {1'b1, 2'd2, {w_q, z_q}};
            if (is_alu_m | is_alu_i | (is_incdec_m & mc_1)) f_we = 1'b1;
            if (is_dad && mc_2) {f_we, f_wd} = {1'b1, o_dbg_regs[RF_F + 7:RF_F + 1], dad_sum[16]};
            if (is_pop && mc_2 && rp == 2'd3) {f_we, f_wd} = {1'b1, z_q & 8'hD5};
            if (mc_1 && (is_mvi_m | is_lxi | is_direct | is_pop_ret | is_jcc | is_jmp |
                         (is_out | is_in) | is_xthl | (is_ccc | is_call)))
              {z_we, z_n} = {1'b1, i_din};
            if (mc_1 && is_incdec_m) {z_we, z_n} = {1'b1, alu_v[15:8]};
            if (mc_2 && (is_direct | is_xthl | (is_ccc | is_call))) {w_we, w_n} = {1'b1, i_din};
            if (mc_3 && is_direct && !o_dbg_op[4]) {w_we, z_we, w_n, z_n} = {2'b11, {w_q, z_q} + 16'd1};
          end
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
          a = seq_asel(mc);
          c = seq_cyc(mc, a);
          {o_cycle, asel_q, dsel_q, last_q} <= {c, a, seq_dsel(mc), seq_last(mc)};
          len_q <= (c == CY_HLT) ? 3'd1 : 3'd3;
          o_io <= (c == CY_IOR || c == CY_IOW);
          // A 1-T cycle (HLT's fifth T-state) has no T2.
          mc_q <= mc;
        end
        if (o_dbg_kind != K_IDLE) begin
          // The work's results. Interrupt state: DI and EI set IE at the
          // end of their fetch (EI with its one-unit shadow); HLT's fifth
          // T-state sets halted; RIM ends the after-TRAP IE. SIM: the
          // interrupt masks (with MSE), the serial output (with SOE).
          if (end_of && (is_di || is_ei)) begin
            o_ie <= is_ei;
            ei_delay_q <= is_ei;
          end
          if (end_mc && is_hlt) o_halted <= 1'b1;
          if (end_of && is_rim) rim_after_trap_q <= 1'b0;
          if (end_of && is_sim) begin
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
          for (b = 0; b < 8; b = b + 1)
            if (rf_we && rf_wa != R_F && rf_pos(rf_wa) == b[2:0]) o_dbg_regs[8*b +: 8] <= rf_wd;
          for (b = 0; b < 3; b = b + 1)  // BC at bits 47:32, DE 31:16, HL 15:0
            if (pair_we && pair_wa == b[1:0]) o_dbg_regs[16*(2-b) +: 16] <= pair_wd;
          if (f_we) o_dbg_regs[RF_F + 7:RF_F] <= f_wd;
          if (end_of && is_xchg) o_dbg_regs[31:0] <= {o_dbg_regs[15:0], o_dbg_regs[31:16]};  // DE <-> HL
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
  end


  // Instruction register and its decoded classes (cpu8085_decode.vh), in
  // a block of their own (a Verilated model then reads the classes' and
  // the opcode fields' wires in the block above where they are used, not
  // as variables computed at every clock): the opcode at the end of T3 of
  // the fetch / INTA; a TRAP / RST x.5 acknowledge runs as RST 7 (FF),
  // loaded at the end of its first cycle's T2 (nothing reads the classes
  // before that cycle ends; its kind is known from T2 on).
  always @(posedge i_clk) begin : instruction
    if (i_rst) begin
      o_dbg_op <= 8'h00;
      cls_q <= decode(8'h00);
    end else if (!i_dbg_load && mc_q == 3'd0) begin
      if (o_tstate == 3'd2 && o_dbg_kind == K_IACK) begin
        o_dbg_op <= 8'hFF;
        cls_q <= decode(8'hFF);
      end
      if (o_tstate == 3'd3 && (o_dbg_kind == K_INSTR || o_dbg_kind == K_INTR)) begin
        o_dbg_op <= i_din;
        cls_q <= decode(i_din);
      end
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
  // The registered classes.
  wire [39:0] classes = cls_q;
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
    if (is_rcc) f_t_expect = cond_ir(ddd) ? 5'd12 : 5'd6;
    if (is_jcc) f_t_expect = cond_ir(ddd) ? 5'd10 : 5'd7;
    if (is_ccc) f_t_expect = cond_ir(ddd) ? 5'd18 : 5'd9;
  end

  always @* begin
    if (f_past_valid) begin
      // The registered classes are the decode of o_dbg_op, one-hot.
      assert (classes == decode(o_dbg_op));
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
