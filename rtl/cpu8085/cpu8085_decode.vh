// cpu8085_decode.vh: the 8085 opcode decoded into instruction-class flags
// (the spirit of SERV's serv_decode and PicoRV32's instr_* flags), as a
// function included inside cpu8085.v's module body. cpu8085.v registers
// its result once per instruction, when the opcode is read (a Verilated
// model then decodes once per instruction, not at every clock), and
// sequences and executes from these flags alone: it has no opcode case of
// its own.
//
// Exactly one class (one of the DC_* bits below, the NOP class included)
// is high for each of the 256 opcodes (the classes partition the opcode
// space; rtl/cpu8085/formal/prove.sh proves it for all 256, and the CPU's
// `ifdef FORMAL block asserts it on the registered flags). Each flag is an
// independent match on opcode bit patterns, so no priority between
// overlapping patterns is needed. Register fields (DDD, SSS, RP) and the
// condition code are plain slices of the opcode and stay in cpu8085.v.
//
// Opcode map (data sheet; M = register index 6):
//   00 DDD SSS  MVI / INR / DCR / rotates / LXI DAD INX DCX / STAX LDAX /
//               SHLD LHLD STA LDA / RIM SIM / NOP
//   01 DDD SSS  MOV (01 110 110 = HLT)
//   10 OOO SSS  ALU A, r / M
//   11 ...      jumps, calls, returns, stack, I/O, ALU immediate, RST
// The undocumented 8085 opcodes 08 10 18 28 38 CB D9 DD ED FD are 4-T
// NOPs here (as in the ISS, docs/i8085.md): class NOP.
//
// decode_all(ir) = {the 39 classes, in this order, then of6, of_only, and
// two groups of classes that share their cycle list}:
//   HLT, MOV r,r, MOV M,r (store to (HL)), MOV r,M (load from (HL)),
//   ALU r (ADD ADC SUB SBB ANA XRA ORA CMP), ALU M, ALU immediate,
//   MVI r, MVI M, INR / DCR r, INR / DCR M, accumulator group (RLC RRC RAL
//   RAR DAA CMA STC CMC), LXI, DAD, INX, DCX, STAX B / D, LDAX B / D,
//   direct (SHLD LHLD STA LDA), RIM, SIM, NOP, Rcc, RET, POP (rp 3: PSW),
//   Jcc, JMP, OUT, IN, XTHL, XCHG, PCHL, SPHL, DI, EI, Ccc, CALL, PUSH
//   (rp 3: PSW), RST n (and the TRAP / RST x.5 acknowledges);
//   of6: an opcode fetch of 6 T-states (data sheet); of_only: no cycle
//   after the opcode fetch (Rcc: only when its condition fails);
//   mem_rmw: MVI M, INR / DCR M (MR or operand, then MW at HL); pop_ret:
//   Rcc RET POP (two reads at SP).
// decode(ir) is the classes without NOP (no work of its own): what
// cpu8085.v registers; decode_of(ir) what its opcode fetch needs.
function [42:0] decode_all;
  input [7:0] ir;
  reg [1:0] grp;
  reg [2:0] f_ddd, f_sss;  // DDD, SSS
  reg [3:0] low;
  reg ddd_m, sss_m, g0, g1, g2, g3;
  reg dc_hlt, dc_mov_rr, dc_mov_mr, dc_mov_rm, dc_alu_r, dc_alu_m, dc_alu_i;
  reg dc_mvi_r, dc_mvi_m, dc_incdec_r, dc_incdec_m, dc_acc;
  reg dc_lxi, dc_dad, dc_inx, dc_dcx, dc_stax, dc_ldax, dc_direct;
  reg dc_rim, dc_sim, dc_nop, dc_rcc, dc_ret, dc_pop, dc_jcc, dc_jmp;
  reg dc_out, dc_in, dc_xthl, dc_xchg, dc_pchl, dc_sphl, dc_di, dc_ei;
  reg dc_ccc, dc_call, dc_push, dc_rst, dc_of6, dc_of_only;
  reg dc_mem_rmw, dc_pop_ret;
  begin
    grp = ir[7:6];
    f_ddd = ir[5:3];
    f_sss = ir[2:0];
    low = ir[3:0];
    ddd_m = (f_ddd == 3'd6);
    sss_m = (f_sss == 3'd6);
    g0 = (grp == 2'd0);
    g1 = (grp == 2'd1);
    g2 = (grp == 2'd2);
    g3 = (grp == 2'd3);

    // 01 DDD SSS: MOV, with HLT in place of MOV M,M.
    dc_hlt = g1 & ddd_m & sss_m;
    dc_mov_rr = g1 & ~ddd_m & ~sss_m;
    dc_mov_mr = g1 & ddd_m & ~sss_m;
    dc_mov_rm = g1 & ~ddd_m & sss_m;

    // 10 OOO SSS: ALU with a register or M; 11 OOO 110: ALU immediate.
    dc_alu_r = g2 & ~sss_m;
    dc_alu_m = g2 & sss_m;
    dc_alu_i = g3 & sss_m;

    // 00 DDD 1xx: MVI, INR, DCR, accumulator group.
    dc_mvi_r = g0 & sss_m & ~ddd_m;
    dc_mvi_m = g0 & sss_m & ddd_m;
    dc_incdec_r = g0 & (f_sss[2:1] == 2'b10) & ~ddd_m;
    dc_incdec_m = g0 & (f_sss[2:1] == 2'b10) & ddd_m;
    dc_acc = g0 & (f_sss == 3'd7);

    // 00 RP x 001 / 011: register pairs.
    dc_lxi = g0 & (low == 4'b0001);
    dc_dad = g0 & (low == 4'b1001);
    dc_inx = g0 & (low == 4'b0011);
    dc_dcx = g0 & (low == 4'b1011);

    // 00 0x x 010: STAX / LDAX; 00 1x x 010: SHLD LHLD STA LDA.
    dc_stax = g0 & ~ir[5] & (low == 4'b0010);
    dc_ldax = g0 & ~ir[5] & (low == 4'b1010);
    dc_direct = g0 & ir[5] & (f_sss == 3'd2);

    // 00 DDD 000: RIM (20), SIM (30), NOP and undocumented NOPs.
    dc_rim = (ir == 8'h20);
    dc_sim = (ir == 8'h30);

    // 11 CCC 000 / 010 / 100: conditional return / jump / call.
    dc_rcc = g3 & (f_sss == 3'd0);
    dc_jcc = g3 & (f_sss == 3'd2);
    dc_ccc = g3 & (f_sss == 3'd4);

    // 11 RP 0 001 / 101: POP / PUSH; 11 NNN 111: RST.
    dc_pop = g3 & (low == 4'b0001);
    dc_push = g3 & (low == 4'b0101);
    dc_rst = g3 & (f_sss == 3'd7);

    // Single opcodes of the 11 group.
    dc_ret = (ir == 8'hC9);
    dc_jmp = (ir == 8'hC3);
    dc_call = (ir == 8'hCD);
    dc_out = (ir == 8'hD3);
    dc_in = (ir == 8'hDB);
    dc_xthl = (ir == 8'hE3);
    dc_xchg = (ir == 8'hEB);
    dc_pchl = (ir == 8'hE9);
    dc_sphl = (ir == 8'hF9);
    dc_di = (ir == 8'hF3);
    dc_ei = (ir == 8'hFB);

    // NOP (00), 08 10 18 28 38, and CB D9 DD ED FD: the one class without
    // work, only part of of_only.
    dc_nop = (g0 & (f_sss == 3'd0) & ~dc_rim & ~dc_sim) |
             (ir == 8'hCB) | (ir == 8'hD9) |
             (g3 & (low == 4'b1101) & ~dc_call);

    // Opcode fetches of 6 T-states (data sheet).
    dc_of6 = dc_inx | dc_dcx | dc_pchl | dc_sphl | dc_call |
             dc_ccc | dc_rcc | dc_rst | dc_push;
    // Instructions done at the end of their opcode fetch.
    dc_of_only = dc_mov_rr | dc_alu_r | dc_incdec_r | dc_acc |
                 dc_inx | dc_dcx | dc_rim | dc_sim | dc_nop |
                 dc_xchg | dc_pchl | dc_sphl | dc_di | dc_ei;

    dc_mem_rmw = dc_mvi_m | dc_incdec_m;
    dc_pop_ret = dc_rcc | dc_ret | dc_pop;

    decode_all = {dc_hlt, dc_mov_rr, dc_mov_mr, dc_mov_rm, dc_alu_r, dc_alu_m,
                  dc_alu_i, dc_mvi_r, dc_mvi_m, dc_incdec_r, dc_incdec_m, dc_acc,
                  dc_lxi, dc_dad, dc_inx, dc_dcx, dc_stax, dc_ldax, dc_direct,
                  dc_rim, dc_sim, dc_nop, dc_rcc, dc_ret, dc_pop, dc_jcc, dc_jmp,
                  dc_out, dc_in, dc_xthl, dc_xchg, dc_pchl, dc_sphl, dc_di, dc_ei,
                  dc_ccc, dc_call, dc_push, dc_rst, dc_of6, dc_of_only,
                  dc_mem_rmw, dc_pop_ret};
  end
endfunction

// The classes without NOP, of6 and of_only, then the groups: what
// cpu8085.v registers.
function [39:0] decode;
  input [7:0] ir;
  reg [20:0] hi;
  reg        unused_nop;  // NOP: no work of its own
  reg [16:0] lo;
  reg [ 1:0] unused_of;   // of6, of_only: decode_of
  reg [ 1:0] groups;
  begin
    {hi, unused_nop, lo, unused_of, groups} = decode_all(ir);
    decode = {hi, lo, groups};
  end
endfunction

// The opcode fetch of op: {of6, of_only, Rcc}, matched on the opcode's
// bit patterns directly, not through decode_all: the sequencer needs only
// these three when the opcode arrives, and a Verilated model evaluates
// this in about a third of decode_all's instructions (decode_all's of6 and
// of_only say the same from the classes; rtl/cpu8085/formal/prove.sh
// proves the two equal for all 256 opcodes).
function [2:0] decode_of;
  input [7:0] op;
  reg [2:0] f_sss;
  reg [3:0] low;
  reg g0, g1, g2, g3, ddd_m, sss_m, step_rp, rcc, of6, of_only;
  begin
    f_sss = op[2:0];
    low = op[3:0];
    g0 = (op[7:6] == 2'd0);
    g1 = (op[7:6] == 2'd1);
    g2 = (op[7:6] == 2'd2);
    g3 = (op[7:6] == 2'd3);
    ddd_m = (op[5:3] == 3'd6);
    sss_m = (f_sss == 3'd6);
    step_rp = g0 & (low[2:0] == 3'b011);  // INX, DCX
    rcc = g3 & (f_sss == 3'd0);
    // INX DCX, Rcc, Ccc, RST, PUSH, CALL, PCHL, SPHL.
    of6 = step_rp | rcc | (g3 & ((f_sss == 3'd4) | (f_sss == 3'd7) | (low == 4'b0101))) |
          (op == 8'hCD) | (op == 8'hE9) | (op == 8'hF9);
    // MOV r,r, ALU r, INR / DCR r, the accumulator group, INX DCX, the
    // 00 DDD 000 column (NOP, RIM, SIM, undocumented), the undocumented
    // CB D9 DD ED FD, XCHG, PCHL, SPHL, DI, EI.
    of_only = (g1 & ~ddd_m & ~sss_m) | (g2 & ~sss_m) | (g0 & (f_sss[2:1] == 2'b10) & ~ddd_m) |
              (g0 & (f_sss == 3'd7)) | step_rp | (g0 & (f_sss == 3'd0)) |
              (op == 8'hCB) | (op == 8'hD9) | (g3 & (low == 4'b1101) & (op != 8'hCD)) |
              (op == 8'hEB) | (op == 8'hE9) | (op == 8'hF9) | (op == 8'hF3) | (op == 8'hFB);
    decode_of = {of6, of_only, rcc};
  end
endfunction

// The class of an opcode as an index (decode_all's order, HLT 0 to RST
// 38), from decode()'s flags: cpu8085.v registers it with the classes and dispatches the work of
// a cycle's end on it by one case (a Verilated model reaches the arm in a
// few bit tests instead of testing each class).
localparam [5:0] C_HLT = 6'd0, C_MOV_RR = 6'd1, C_MOV_MR = 6'd2, C_MOV_RM = 6'd3;
localparam [5:0] C_ALU_R = 6'd4, C_ALU_M = 6'd5, C_ALU_I = 6'd6, C_MVI_R = 6'd7;
localparam [5:0] C_MVI_M = 6'd8, C_INCDEC_R = 6'd9, C_INCDEC_M = 6'd10, C_ACC = 6'd11;
localparam [5:0] C_LXI = 6'd12, C_DAD = 6'd13, C_INX = 6'd14, C_DCX = 6'd15;
localparam [5:0] C_STAX = 6'd16, C_LDAX = 6'd17, C_DIRECT = 6'd18, C_RIM = 6'd19;
localparam [5:0] C_SIM = 6'd20, C_NOP = 6'd21, C_RCC = 6'd22, C_RET = 6'd23;
localparam [5:0] C_POP = 6'd24, C_JCC = 6'd25, C_JMP = 6'd26, C_OUT = 6'd27;
localparam [5:0] C_IN = 6'd28, C_XTHL = 6'd29, C_XCHG = 6'd30, C_PCHL = 6'd31;
localparam [5:0] C_SPHL = 6'd32, C_DI = 6'd33, C_EI = 6'd34, C_CCC = 6'd35;
localparam [5:0] C_CALL = 6'd36, C_PUSH = 6'd37, C_RST = 6'd38;
function [5:0] class_of;
  input [39:0] cls;  // decode()'s result
  integer i;
  begin
    // decode() has no NOP: its bits 39..19 are classes 0..20 (HLT..SIM),
    // 18..2 classes 22..38 (Rcc..RST), 1..0 the groups.
    class_of = C_NOP;
    for (i = 0; i < 21; i = i + 1)
      if (cls[39 - i]) class_of = i[5:0];
    for (i = 22; i < 39; i = i + 1)
      if (cls[40 - i]) class_of = i[5:0];
  end
endfunction

