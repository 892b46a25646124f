// differs_all(r, g): the netlist's outputs g differ from the RTL's r where
// it counts: a bit the RTL defines (0 or 1) that the netlist does not equal
// (another value, X or Z). Included inside a gate-level testbench module,
// after its localparam OB (the number of output bits compared).
function differs_all(input [OB-1:0] r, input [OB-1:0] g);
  integer b;
  begin
    differs_all = 1'b0;
    for (b = 0; b < OB; b = b + 1)
      if ((r[b] === 1'b0 || r[b] === 1'b1) && g[b] !== r[b]) differs_all = 1'b1;
  end
endfunction
