// inc_terms.vh: the carry-free test "a + 1 == b" (mod 2^(W+1)) used by
// interp_dp's and blk_prep's flags, included inside each module after W
// (no include guard, like interp_block.vh).
//
// (a + 1) mod 2^(W+1) == b without an adder: a + ~b == -2, checked bit
// by bit against the carries such a sum has (the carry into bit i is a
// function of bit i - 1 of both operands: c(1) = a(0) | ~b(0), c(i) =
// a(i-1) & ~b(i-1) above), so each bit is one 4-input term and the
// test is their AND. W + 1 bit operands: a W-bit value zero-extended
// compares without wrap-around.
  function automatic [W:0] inc_terms(input [W:0] a, input [W:0] b);
    integer i;
    begin
      inc_terms[0] = a[0] ^ b[0];
      inc_terms[1] = (a[1] ^ b[1]) == (a[0] | ~b[0]);
      for (i = 2; i <= W; i = i + 1)
        inc_terms[i] = (a[i] ^ b[i]) == (a[i-1] & ~b[i-1]);
    end
  endfunction
