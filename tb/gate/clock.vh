// The gate-level testbenches' clock: `clk` toggles every 5 time units,
// `clock` counts its rising edges, `armed` is high from the first edge
// with reset released (outputs are compared only then). Included inside a
// testbench module that declares `reg clk` and `reg rst`.
integer clock = 0;
reg armed = 1'b0;
always #5 clk = ~clk;
always @(posedge clk) begin
  clock <= clock + 1;
  if (~rst) armed <= 1'b1;
end
