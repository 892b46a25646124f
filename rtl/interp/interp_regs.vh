// Generated from rtl/interp/regmap.def by rtl/interp/regmap_gen.cmake: do not edit.
// Register offsets (byte addresses) and field positions of interp_top.
// Waiver: a table; no one module uses every entry of it.
/* verilator lint_off UNUSEDPARAM */
localparam [7:0] A_ID = 8'h00;
localparam [31:0] R_ID = 32'h494E5450;
localparam [7:0] A_PARAMS = 8'h04;
localparam integer PARAMS_W = 0;  // width 8
localparam integer PARAMS_QDEPTH = 8;  // width 8
localparam [7:0] A_CTRL = 8'h08;
localparam [31:0] R_CTRL = 32'h0;
localparam integer CTRL_SRC = 0;  // width 2
localparam integer CTRL_ABORT = 2;  // width 1
localparam integer CTRL_CLEAR = 3;  // width 1
localparam [7:0] A_STATUS = 8'h0C;
localparam [31:0] R_STATUS = 32'h2;
localparam integer STATUS_BUSY = 0;  // width 1
localparam integer STATUS_EMPTY = 1;  // width 1
localparam integer STATUS_FULL = 2;  // width 1
localparam integer STATUS_OVERRUN = 3;  // width 1
localparam integer STATUS_REJECT = 4;  // width 1
localparam integer STATUS_LEVEL = 8;  // width 8
localparam [7:0] A_FEED = 8'h10;
localparam [31:0] R_FEED = 32'h0;
localparam [7:0] A_STEP_LEN = 8'h14;
localparam [31:0] R_STEP_LEN = 32'h1;
localparam [7:0] A_STEP_SPACE = 8'h18;
localparam [31:0] R_STEP_SPACE = 32'h1;
localparam [7:0] A_DIR_SETUP = 8'h1C;
localparam [31:0] R_DIR_SETUP = 32'h1;
localparam [7:0] A_DIR_HOLD = 8'h20;
localparam [31:0] R_DIR_HOLD = 32'h1;
localparam [7:0] A_OVR_COUNT = 8'h24;
localparam [31:0] R_OVR_COUNT = 32'h0;
localparam [7:0] A_POS_X = 8'h28;
localparam [31:0] R_POS_X = 32'h0;
localparam [7:0] A_POS_Y = 8'h2C;
localparam [31:0] R_POS_Y = 32'h0;
localparam [7:0] A_MOVES = 8'h30;
localparam [31:0] R_MOVES = 32'h0;
localparam [7:0] A_BLK_MODE = 8'h34;
localparam [31:0] R_BLK_MODE = 32'h0;
localparam integer BLK_MODE_ARC = 0;  // width 1
localparam integer BLK_MODE_CW = 1;  // width 1
localparam integer BLK_MODE_SXN = 2;  // width 1
localparam integer BLK_MODE_SYN = 3;  // width 1
localparam integer BLK_MODE_Q = 4;  // width 2
localparam integer BLK_MODE_K = 6;  // width 3
localparam [7:0] A_BLK_XS = 8'h38;
localparam [31:0] R_BLK_XS = 32'h0;
localparam [7:0] A_BLK_YS = 8'h3C;
localparam [31:0] R_BLK_YS = 32'h0;
localparam [7:0] A_BLK_XE = 8'h40;
localparam [31:0] R_BLK_XE = 32'h0;
localparam [7:0] A_BLK_YE = 8'h44;
localparam [31:0] R_BLK_YE = 32'h0;
localparam [7:0] A_PUSH = 8'h48;
/* verilator lint_on UNUSEDPARAM */
