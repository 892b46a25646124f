`default_nettype none
// cpu8085_alu: the 8085's 8-bit arithmetic and logic, purely combinational.
//
// One operation per i_op (the ALU_* codes below); the result and the whole
// new flag byte F come out together. Flags follow docs/i8085.md (the ISS's
// contract): F = S Z 0 AC 0 P 0 CY on the 8085 (bits 5, 3 and 1 read 0),
// AC after ANA/ANI is 1, after XRA/ORA 0; for subtraction AC is the carry
// out of bit 3 of A + ~B + ~borrow (the 8080/8085 adder), as the ISS does.
// Operations that leave a flag alone copy it from i_f.
module cpu8085_alu (
    input  wire [4:0] i_op,  // ALU_* operation
    input  wire [7:0] i_a,   // accumulator
    input  wire [7:0] i_b,   // operand (register, memory or immediate)
    input  wire [7:0] i_f,   // flags before the operation
    output reg  [7:0] o_res, // result (A for 0..7 and 10..15, the operand for 8/9)
    output reg  [7:0] o_f    // flags after the operation
);
  // Operation codes; 0..7 are the opcode's bits 5:3 of the ALU group.
  localparam [4:0] ALU_ADD = 5'd0, ALU_ADC = 5'd1, ALU_SUB = 5'd2, ALU_SBB = 5'd3;
  localparam [4:0] ALU_ANA = 5'd4, ALU_XRA = 5'd5, ALU_ORA = 5'd6, ALU_CMP = 5'd7;
  localparam [4:0] ALU_INR = 5'd8, ALU_DCR = 5'd9;
  localparam [4:0] ALU_RLC = 5'd10, ALU_RRC = 5'd11, ALU_RAL = 5'd12, ALU_RAR = 5'd13;
  localparam [4:0] ALU_DAA = 5'd14, ALU_CMA = 5'd15, ALU_STC = 5'd16, ALU_CMC = 5'd17;

  wire cy_in = i_f[0];
  wire ac_in = i_f[4];

  // One adder for ADD/ADC/SUB/SBB/CMP: A + (B or ~B) + carry-in.
  wire       is_sub = (i_op == ALU_SUB) || (i_op == ALU_SBB) || (i_op == ALU_CMP);
  wire       use_cy = (i_op == ALU_ADC) || (i_op == ALU_SBB);
  wire [7:0] add_b  = is_sub ? ~i_b : i_b;
  wire       add_ci = is_sub ? ~(use_cy & cy_in) : (use_cy & cy_in);
  wire [4:0] add_lo = {1'b0, i_a[3:0]} + {1'b0, add_b[3:0]} + {4'b0, add_ci};
  wire [8:0] add_r  = {1'b0, i_a} + {1'b0, add_b} + {8'b0, add_ci};
  wire       add_ac = add_lo[4];  // carry out of bit 3

  // INR/DCR on the operand.
  wire [7:0] inr_r = i_b + 8'd1;
  wire [7:0] dcr_r = i_b - 8'd1;

  // DAA: the two corrections of the 8085 manual.
  wire       daa_lo  = (i_a[3:0] > 4'd9) || ac_in;
  wire [8:0] daa_1   = {1'b0, i_a} + (daa_lo ? 9'h006 : 9'h000);
  wire       daa_hi  = (daa_1[7:4] > 4'd9) || cy_in || daa_1[8];
  wire [8:0] daa_2   = {1'b0, daa_1[7:0]} + (daa_hi ? 9'h060 : 9'h000);
  wire       daa_ac  = (i_a[3:0] > 4'd9);
  // The low nibble sum only yields AC; DAA's ninth bit is its CY, computed apart.
  wire [4:0] unused_bits = {add_lo[3:0], daa_2[8]};

  // Sign, zero, parity and the flag byte from a result.
  function [7:0] szp;
    input [7:0] r;
    input       ac;
    input       cy;
    begin
      szp = {r[7], (r == 8'h00), 1'b0, ac, 1'b0, ~^r, 1'b0, cy};
    end
  endfunction

  always @* begin
    o_res = i_a;
    o_f   = i_f;
    case (i_op)
      ALU_ADD, ALU_ADC: begin
        o_res = add_r[7:0];
        o_f   = szp(add_r[7:0], add_ac, add_r[8]);
      end
      ALU_SUB, ALU_SBB, ALU_CMP: begin
        o_res = (i_op == ALU_CMP) ? i_a : add_r[7:0];
        o_f   = szp(add_r[7:0], add_ac, ~add_r[8]);
      end
      ALU_ANA: begin
        o_res = i_a & i_b;
        o_f   = szp(i_a & i_b, 1'b1, 1'b0);
      end
      ALU_XRA: begin
        o_res = i_a ^ i_b;
        o_f   = szp(i_a ^ i_b, 1'b0, 1'b0);
      end
      ALU_ORA: begin
        o_res = i_a | i_b;
        o_f   = szp(i_a | i_b, 1'b0, 1'b0);
      end
      ALU_INR: begin
        o_res = inr_r;
        o_f   = szp(inr_r, (inr_r[3:0] == 4'h0), cy_in);
      end
      ALU_DCR: begin
        o_res = dcr_r;
        o_f   = szp(dcr_r, (dcr_r[3:0] != 4'hF), cy_in);
      end
      ALU_RLC: begin
        o_res = {i_a[6:0], i_a[7]};
        o_f   = {i_f[7:1], i_a[7]};
      end
      ALU_RRC: begin
        o_res = {i_a[0], i_a[7:1]};
        o_f   = {i_f[7:1], i_a[0]};
      end
      ALU_RAL: begin
        o_res = {i_a[6:0], cy_in};
        o_f   = {i_f[7:1], i_a[7]};
      end
      ALU_RAR: begin
        o_res = {cy_in, i_a[7:1]};
        o_f   = {i_f[7:1], i_a[0]};
      end
      ALU_DAA: begin
        o_res = daa_2[7:0];
        o_f   = szp(daa_2[7:0], daa_ac, daa_hi);
      end
      ALU_CMA: o_res = ~i_a;
      ALU_STC: o_f = {i_f[7:1], 1'b1};
      ALU_CMC: o_f = {i_f[7:1], ~cy_in};
      default: ;
    endcase
  end
endmodule

`default_nettype wire
