`default_nettype none
// cpu8085_decode: the 8085 instruction register decoded once into
// instruction-class flags (the spirit of SERV's serv_decode and PicoRV32's
// instr_* flags). cpu8085.v sequences and executes from these flags alone;
// it has no opcode case of its own.
//
// Exactly one class (an o_is_* flag, or the internal is_nop) is high for
// each of the 256 opcodes (the classes partition the opcode space; the
// `ifdef FORMAL block below asserts it). Each flag is
// an independent match on opcode bit patterns, so no priority between
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
// NOPs here (as in the ISS, docs/i8085.md): class is_nop.
module cpu8085_decode (
    input  wire [7:0] i_ir,          // instruction register
    // one-hot instruction classes
    output wire       o_is_hlt,      // HLT
    output wire       o_is_mov_rr,   // MOV r,r
    output wire       o_is_mov_mr,   // MOV M,r (store to (HL))
    output wire       o_is_mov_rm,   // MOV r,M (load from (HL))
    output wire       o_is_alu_r,    // ADD ADC SUB SBB ANA XRA ORA CMP r
    output wire       o_is_alu_m,    // the same with M
    output wire       o_is_alu_i,    // ADI ACI SUI SBI ANI XRI ORI CPI
    output wire       o_is_mvi_r,    // MVI r
    output wire       o_is_mvi_m,    // MVI M
    output wire       o_is_incdec_r, // INR r / DCR r
    output wire       o_is_incdec_m, // INR M / DCR M
    output wire       o_is_acc,      // RLC RRC RAL RAR DAA CMA STC CMC
    output wire       o_is_lxi,      // LXI rp
    output wire       o_is_dad,      // DAD rp
    output wire       o_is_inx,      // INX rp
    output wire       o_is_dcx,      // DCX rp
    output wire       o_is_stax,     // STAX B / D
    output wire       o_is_ldax,     // LDAX B / D
    output wire       o_is_direct,   // SHLD LHLD STA LDA (address operand)
    output wire       o_is_rim,      // RIM
    output wire       o_is_sim,      // SIM
    output wire       o_is_rcc,      // Rcc
    output wire       o_is_ret,      // RET
    output wire       o_is_pop,      // POP rp (rp 3: PSW)
    output wire       o_is_jcc,      // Jcc
    output wire       o_is_jmp,      // JMP
    output wire       o_is_out,      // OUT port
    output wire       o_is_in,       // IN port
    output wire       o_is_xthl,     // XTHL
    output wire       o_is_xchg,     // XCHG
    output wire       o_is_pchl,     // PCHL
    output wire       o_is_sphl,     // SPHL
    output wire       o_is_di,       // DI
    output wire       o_is_ei,       // EI
    output wire       o_is_ccc,      // Ccc
    output wire       o_is_call,     // CALL
    output wire       o_is_push,     // PUSH rp (rp 3: PSW)
    output wire       o_is_rst,      // RST n (and the TRAP / RST x.5 acks)
    // groups of the classes above
    output wire       o_of6,         // opcode fetch of 6 T-states
    output wire       o_of_only      // no cycle after the opcode fetch
                                     // (Rcc: only when its condition fails)
);
  wire [1:0] grp = i_ir[7:6];
  wire [2:0] ddd = i_ir[5:3];
  wire [2:0] sss = i_ir[2:0];
  wire [3:0] low = i_ir[3:0];
  wire       ddd_m = (ddd == 3'd6);
  wire       sss_m = (sss == 3'd6);
  wire       g0 = (grp == 2'd0);
  wire       g1 = (grp == 2'd1);
  wire       g2 = (grp == 2'd2);
  wire       g3 = (grp == 2'd3);

  // 01 DDD SSS: MOV, with HLT in place of MOV M,M.
  assign o_is_hlt = g1 & ddd_m & sss_m;
  assign o_is_mov_rr = g1 & ~ddd_m & ~sss_m;
  assign o_is_mov_mr = g1 & ddd_m & ~sss_m;
  assign o_is_mov_rm = g1 & ~ddd_m & sss_m;

  // 10 OOO SSS: ALU with a register or M; 11 OOO 110: ALU immediate.
  assign o_is_alu_r = g2 & ~sss_m;
  assign o_is_alu_m = g2 & sss_m;
  assign o_is_alu_i = g3 & sss_m;

  // 00 DDD 1xx: MVI, INR, DCR, accumulator group.
  assign o_is_mvi_r = g0 & sss_m & ~ddd_m;
  assign o_is_mvi_m = g0 & sss_m & ddd_m;
  assign o_is_incdec_r = g0 & (sss[2:1] == 2'b10) & ~ddd_m;
  assign o_is_incdec_m = g0 & (sss[2:1] == 2'b10) & ddd_m;
  assign o_is_acc = g0 & (sss == 3'd7);

  // 00 RP x 001 / 011: register pairs.
  assign o_is_lxi = g0 & (low == 4'b0001);
  assign o_is_dad = g0 & (low == 4'b1001);
  assign o_is_inx = g0 & (low == 4'b0011);
  assign o_is_dcx = g0 & (low == 4'b1011);

  // 00 0x x 010: STAX / LDAX; 00 1x x 010: SHLD LHLD STA LDA.
  assign o_is_stax = g0 & ~i_ir[5] & (low == 4'b0010);
  assign o_is_ldax = g0 & ~i_ir[5] & (low == 4'b1010);
  assign o_is_direct = g0 & i_ir[5] & (sss == 3'd2);

  // 00 DDD 000: RIM (20), SIM (30), NOP and undocumented NOPs.
  assign o_is_rim = (i_ir == 8'h20);
  assign o_is_sim = (i_ir == 8'h30);

  // 11 CCC 000 / 010 / 100: conditional return / jump / call.
  assign o_is_rcc = g3 & (sss == 3'd0);
  assign o_is_jcc = g3 & (sss == 3'd2);
  assign o_is_ccc = g3 & (sss == 3'd4);

  // 11 RP 0 001 / 101: POP / PUSH; 11 NNN 111: RST.
  assign o_is_pop = g3 & (low == 4'b0001);
  assign o_is_push = g3 & (low == 4'b0101);
  assign o_is_rst = g3 & (sss == 3'd7);

  // Single opcodes of the 11 group.
  assign o_is_ret = (i_ir == 8'hC9);
  assign o_is_jmp = (i_ir == 8'hC3);
  assign o_is_call = (i_ir == 8'hCD);
  assign o_is_out = (i_ir == 8'hD3);
  assign o_is_in = (i_ir == 8'hDB);
  assign o_is_xthl = (i_ir == 8'hE3);
  assign o_is_xchg = (i_ir == 8'hEB);
  assign o_is_pchl = (i_ir == 8'hE9);
  assign o_is_sphl = (i_ir == 8'hF9);
  assign o_is_di = (i_ir == 8'hF3);
  assign o_is_ei = (i_ir == 8'hFB);

  // NOP (00), 08 10 18 28 38, and CB D9 DD ED FD: no output of its own (a
  // NOP is the one class without work), only part of o_of_only.
  wire is_nop = (g0 & (sss == 3'd0) & ~o_is_rim & ~o_is_sim) |
                (i_ir == 8'hCB) | (i_ir == 8'hD9) |
                (g3 & (low == 4'b1101) & ~o_is_call);

  // Opcode fetches of 6 T-states (data sheet).
  assign o_of6 = o_is_inx | o_is_dcx | o_is_pchl | o_is_sphl | o_is_call |
                 o_is_ccc | o_is_rcc | o_is_rst | o_is_push;
  // Instructions done at the end of their opcode fetch.
  assign o_of_only = o_is_mov_rr | o_is_alu_r | o_is_incdec_r | o_is_acc |
                     o_is_inx | o_is_dcx | o_is_rim | o_is_sim | is_nop |
                     o_is_xchg | o_is_pchl | o_is_sphl | o_is_di | o_is_ei;

`ifdef FORMAL
  // The classes partition the opcode space: exactly one flag is high.
  wire [38:0] f_classes = {
    o_is_hlt, o_is_mov_rr, o_is_mov_mr, o_is_mov_rm, o_is_alu_r, o_is_alu_m,
    o_is_alu_i, o_is_mvi_r, o_is_mvi_m, o_is_incdec_r, o_is_incdec_m,
    o_is_acc, o_is_lxi, o_is_dad, o_is_inx, o_is_dcx, o_is_stax, o_is_ldax,
    o_is_direct, o_is_rim, o_is_sim, is_nop, o_is_rcc, o_is_ret, o_is_pop,
    o_is_jcc, o_is_jmp, o_is_out, o_is_in, o_is_xthl, o_is_xchg, o_is_pchl,
    o_is_sphl, o_is_di, o_is_ei, o_is_ccc, o_is_call, o_is_push, o_is_rst};
  always @* begin
    assert (f_classes != 39'd0);
    assert ((f_classes & (f_classes - 39'd1)) == 39'd0);
  end
`endif
endmodule

`default_nettype wire
