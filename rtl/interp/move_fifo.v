// move_fifo: the move queue. First-word-fall-through FIFO: the head block
// is on o_data whenever o_valid is high, and i_pop takes it. The storage is
// a synchronous-read memory (an iCE40 block RAM) behind one output
// register, so the head is always a register. The caller never pushes
// while the memory is full (interp_core refuses such a push before its
// block preparation, from its registered full flag): the write port has no
// full test of its own, so no pointer subtraction reaches the block RAM's
// write enable.
`default_nettype none

module move_fifo #(
    parameter integer WIDTH = 16,  // block width in bits
    parameter integer AW = 4       // log2 of the memory depth
) (
    input  wire             i_clk,
    input  wire             i_rst,
    input  wire             i_flush,    // drop every queued block
    input  wire             i_push,
    input  wire [WIDTH-1:0] i_data,
    input  wire             i_pop,
    output reg              o_valid,
    output reg  [WIDTH-1:0] o_data,
    output wire [AW+1:0]    o_level,    // blocks queued, head included
    output wire [AW:0]      o_used      // blocks in the memory (head excluded)
);

  localparam integer DEPTH = 1 << AW;

  // The memory is never read at the address written in the same clock (a
  // read needs the memory not empty, a write goes to the free end and the
  // memory is never full then): no_rw_check tells yosys not to emulate a
  // read-during-write behaviour around the block RAM.
  (* no_rw_check *)
  reg [WIDTH-1:0] mem [0:DEPTH-1];
  reg [AW:0] wptr_q, rptr_q;

  wire [AW:0] used = wptr_q - rptr_q;
  wire mem_empty = (wptr_q == rptr_q);  // equality: shorter than used == 0
  assign o_used = used;
  assign o_level = {1'b0, used} + {{(AW+1){1'b0}}, o_valid};

  wire wr = i_push;
  // rd = ~empty & (~o_valid | i_pop): the pop (the caller's load decision)
  // is the late input, so it comes one LUT before rd; the other terms are
  // from flip-flops alone, kept apart (LUT boundaries for abc).
  (* keep *) wire rd_ne = ~mem_empty;
  (* keep *) wire rd_idle = ~mem_empty & ~o_valid;
  wire rd = rd_idle | (rd_ne & i_pop);

  // Memory write port.
  always @(posedge i_clk) begin
    if (wr) mem[wptr_q[AW-1:0]] <= i_data;
  end

  // Memory read port into the output register.
  always @(posedge i_clk) begin
    if (rd) o_data <= mem[rptr_q[AW-1:0]];
  end

  // Write pointer.
  always @(posedge i_clk) begin
    if (i_rst | i_flush) wptr_q <= {(AW+1){1'b0}};
    else if (wr) wptr_q <= wptr_q + 1'b1;
  end

  // Read pointer. Its enable is one LUT after the pop too: the reset is
  // in a kept term from flip-flops and inputs (an iCE40 flip-flop's reset
  // acts only with its enable, so a reset written before the enable makes
  // the enable rd | reset, a LUT after rd).
  (* keep *) wire rd_idle_r = rd_idle | i_rst | i_flush;
  wire rptr_ce = rd_idle_r | (rd_ne & i_pop);
  always @(posedge i_clk) begin
    if (rptr_ce) rptr_q <= (i_rst | i_flush) ? {(AW+1){1'b0}} : rptr_q + 1'b1;
  end

  // Head valid: after a read, or kept when not popped (a read follows a
  // pop whenever the memory holds a block). No clock enable: the pop is one
  // LUT from the flip-flop.
  always @(posedge i_clk) begin
    if (i_rst | i_flush) o_valid <= 1'b0;
    else o_valid <= rd_ne | (o_valid & ~i_pop);
  end

endmodule
