// cpu8085_alu.vh: the 8085's 8-bit arithmetic and logic as functions,
// included inside cpu8085.v's module body (not a module: a function is
// evaluated by a Verilated model only where it is called, i.e. at the end
// of a cycle that writes, not at every clock).
//
// alu_exec: one operation per op (the ALU_* codes below); the result and
// the whole new flag byte F come out together, {result, F}. Flags follow
// docs/i8085.md (the ISS's contract): F = S Z 0 AC 0 P 0 CY on the 8085
// (bits 5, 3 and 1 read 0), AC after ANA/ANI is 1, after XRA/ORA 0; for
// subtraction AC is the carry out of bit 3 of A + ~B + ~borrow (the
// 8080/8085 adder), as the ISS does. Operations that leave a flag alone
// copy it from f. The result is A for 0..7 and 10..15, the operand for 8/9.

// Operation codes; 0..7 are the opcode's bits 5:3 of the ALU group.
localparam [4:0] ALU_ADD = 5'd0, ALU_ADC = 5'd1, ALU_SUB = 5'd2, ALU_SBB = 5'd3;
localparam [4:0] ALU_ANA = 5'd4, ALU_XRA = 5'd5, ALU_ORA = 5'd6, ALU_CMP = 5'd7;
localparam [4:0] ALU_INR = 5'd8, ALU_DCR = 5'd9;
localparam [4:0] ALU_RLC = 5'd10, ALU_RRC = 5'd11, ALU_RAL = 5'd12, ALU_RAR = 5'd13;
localparam [4:0] ALU_DAA = 5'd14, ALU_CMA = 5'd15, ALU_STC = 5'd16, ALU_CMC = 5'd17;

// Sign, zero, parity and the flag byte from a result.
function [7:0] alu_szp;
  input [7:0] r;
  input       ac;
  input       cy;
  begin
    alu_szp = {r[7], (r == 8'h00), 1'b0, ac, 1'b0, ~^r, 1'b0, cy};
  end
endfunction

// ADD ADC SUB SBB CMP: one adder, A + (B or ~B) + carry-in; {result, F}.
function [15:0] alu_add;
  input [4:0] op;
  input [7:0] a;
  input [7:0] b;
  input       cy_in;
  reg         is_sub, ci;
  reg   [7:0] bb;
  reg   [8:0] r;
  begin
    is_sub = (op == ALU_SUB) || (op == ALU_SBB) || (op == ALU_CMP);
    ci = ((op == ALU_ADC) || (op == ALU_SBB)) & cy_in;
    bb = is_sub ? ~b : b;
    if (is_sub) ci = ~ci;
    r = {1'b0, a} + {1'b0, bb} + {8'b0, ci};
    // AC, the carry out of bit 3, is what bit 4 of the sum got besides its
    // operands' bits.
    alu_add = {(op == ALU_CMP) ? a : r[7:0], alu_szp(r[7:0], r[4] ^ a[4] ^ bb[4], r[8] ^ is_sub)};
  end
endfunction

// DAA: the two corrections of the 8085 manual; {result, F}.
function [15:0] alu_daa;
  input [7:0] a;
  input       ac_in;
  input       cy_in;
  reg         lo, hi;
  reg   [8:0] d1;
  reg   [7:0] d2;
  begin
    lo = (a[3:0] > 4'd9) || ac_in;
    d1 = {1'b0, a} + (lo ? 9'h006 : 9'h000);
    hi = (d1[7:4] > 4'd9) || cy_in || d1[8];
    d2 = d1[7:0] + (hi ? 8'h60 : 8'h00);
    alu_daa = {d2, alu_szp(d2, (a[3:0] > 4'd9), hi)};
  end
endfunction

// The operation op on A (a), the operand (b) and the flags (f): {result, F}.
function [15:0] alu_exec;
  input [4:0] op;
  input [7:0] a;
  input [7:0] b;
  input [7:0] f;
  reg   [7:0] r;
  begin
    alu_exec = {a, f};
    case (op)
      ALU_ADD, ALU_ADC, ALU_SUB, ALU_SBB, ALU_CMP: alu_exec = alu_add(op, a, b, f[0]);
      ALU_ANA: alu_exec = {a & b, alu_szp(a & b, 1'b1, 1'b0)};
      ALU_XRA: alu_exec = {a ^ b, alu_szp(a ^ b, 1'b0, 1'b0)};
      ALU_ORA: alu_exec = {a | b, alu_szp(a | b, 1'b0, 1'b0)};
      ALU_INR: begin
        r = b + 8'd1;
        alu_exec = {r, alu_szp(r, (r[3:0] == 4'h0), f[0])};
      end
      ALU_DCR: begin
        r = b - 8'd1;
        alu_exec = {r, alu_szp(r, (r[3:0] != 4'hF), f[0])};
      end
      ALU_RLC: alu_exec = {a[6:0], a[7], f[7:1], a[7]};
      ALU_RRC: alu_exec = {a[0], a[7:1], f[7:1], a[0]};
      ALU_RAL: alu_exec = {a[6:0], f[0], f[7:1], a[7]};
      ALU_RAR: alu_exec = {f[0], a[7:1], f[7:1], a[0]};
      ALU_DAA: alu_exec = alu_daa(a, f[4], f[0]);
      ALU_CMA: alu_exec = {~a, f};
      ALU_STC: alu_exec = {a, f[7:1], 1'b1};
      ALU_CMC: alu_exec = {a, f[7:1], ~f[0]};
      default: ;
    endcase
  end
endfunction
