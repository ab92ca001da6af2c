// vec_player.vh: the vector player shared by the replay testbenches (docs/vectors.md).
//
// Included inside a testbench module that declares, before the include:
//   localparam W_IN  = ...;   // width of the input columns (rst first)
//   localparam W_OUT = ...;   // width of the output columns
//   localparam UNIT  = "...";  // the `unit` of the .meta file
//   parameter  CHIP  = ...;   // the CHIP parameter of the DUT (checked against chip_code)
// and after it connects the DUT to `vin` (inputs, MSB = first column) and `vout`; `vin_nx` is
// the next line's inputs (the last line's own on the last line), for a testbench that forms a
// register input one edge ahead as the chip does.
//
// Plusargs: +hex=FILE +cols=FILE +meta=FILE [+max_report=N]. The player reads .meta (cycles,
// width, mask, chip_code, unit) and .cols (column names and widths), loads .hex with $readmemh,
// checks the line count and every line's length (digits), framing (sentinel digit A, XOR of all
// digits 0) and content (no X),
// then drives one line per CLK cycle and compares the outputs after each rising edge under
// the mask. X or Z on a compared output is a failure. It ends with `N passed, N failed`
// (passed/failed = lines; a corrupt file counts every line as failed).

    parameter DEPTH = 1 << 20;                 // largest .hex the memory holds
    localparam W_PORTS = W_IN + W_OUT;
    localparam W_CHECK = 4 + (4 - W_PORTS % 4) % 4;
    localparam W_LINE  = 4 + W_PORTS + W_CHECK;
    localparam MAXCOLS = 64;

    reg                clk = 1'b1;
    reg  [W_IN-1:0]    vin, vin_nx;
    wire [W_OUT-1:0]   vout;

    reg  [W_LINE-1:0]  mem [0:DEPTH-1];
    reg  [W_OUT-1:0]   mask;
    reg  [8*256-1:0]   hex_file, cols_file, meta_file;
    reg  [8*64-1:0]    key, sval, kind;
    reg  [8*64-1:0]    col_name [0:MAXCOLS-1];
    integer            col_w [0:MAXCOLS-1];
    integer            col_out [0:MAXCOLS-1];
    integer            ncols, fd, r, i, k, n_cycles, width, chip_code, max_report;
    integer            passed, failed, reported, corrupt, w, lo, sum_in, sum_out;
    reg  [63:0]        cm;
    reg  [8*(W_LINE/4+16)-1:0] text;
    integer            nlines, len;
    reg  [W_LINE-1:0]  line, line_nx;
    reg  [W_OUT-1:0]   exp_out, got, diff;
    reg  [8*64-1:0]    meta_unit;
    reg                meta_ok;

    // XOR of all hex digits of a line (0 for a well-formed line)
    function [3:0] digit_xor;
        input [W_LINE-1:0] l;
        integer j;
        begin
            digit_xor = 4'h0;
            for (j = 0; j < W_LINE; j = j + 4)
                digit_xor = digit_xor ^ l[j +: 4];
        end
    endfunction

    task fail_corrupt;
        begin
            corrupt = 1;
        end
    endtask

    // free-running clock, period 10 time units, high at time 0: the first edge is the falling one
    // (at 5), where line 0's inputs are applied, and the first rising edge (at 10) is line 0's
    always #5 clk = ~clk;

    initial begin
        vin = {W_IN{1'b0}};
        vin_nx = {W_IN{1'b0}};
        passed = 0; failed = 0; reported = 0; corrupt = 0;
        n_cycles = -1; width = -1; chip_code = -1; mask = {W_OUT{1'b1}};
        meta_unit = 0; meta_ok = 1'b1;
        if (!$value$plusargs("max_report=%d", max_report)) max_report = 10;
        if (!$value$plusargs("hex=%s", hex_file) || !$value$plusargs("cols=%s", cols_file)
            || !$value$plusargs("meta=%s", meta_file)) begin
            $display("usage: +hex=FILE.hex +cols=FILE.cols +meta=FILE.meta [+max_report=N]");
            $display("0 passed, 1 failed");
            $finish;
        end
        // ---- .meta -------------------------------------------------------------------
        fd = $fopen(meta_file, "r");
        if (fd == 0) begin
            $display("ERROR: cannot open %0s", meta_file);
            $display("0 passed, 1 failed");
            $finish;
        end
        while (!$feof(fd)) begin
            key = 0;
            r = $fscanf(fd, "%s", key);
            if (r == 1) begin
                if (key == "cycles")         r = $fscanf(fd, "%d", n_cycles);
                else if (key == "width")     r = $fscanf(fd, "%d", width);
                else if (key == "chip_code") r = $fscanf(fd, "%d", chip_code);
                else if (key == "mask")      r = $fscanf(fd, "%h", mask);
                else if (key == "unit")      r = $fscanf(fd, "%s", meta_unit);
                else                         r = $fgets(sval, fd);   // rest of the line
            end
        end
        $fclose(fd);
        if (n_cycles < 1 || n_cycles >= DEPTH) begin
            $display("ERROR: %0s: cycles %0d missing or not below DEPTH = %0d", meta_file, n_cycles, DEPTH);
            meta_ok = 1'b0;
        end
        if (width != W_LINE) begin
            $display("ERROR: %0s: width %0d, this testbench reads lines of %0d bits", meta_file, width, W_LINE);
            meta_ok = 1'b0;
        end
        if (meta_unit != UNIT) begin
            $display("ERROR: %0s: unit '%0s', this testbench replays unit '%0s'", meta_file, meta_unit, UNIT);
            meta_ok = 1'b0;
        end
        if (chip_code != CHIP) begin
            $display("ERROR: %0s: chip_code %0d, the DUT is built with CHIP = %0d", meta_file, chip_code, CHIP);
            meta_ok = 1'b0;
        end
        // ---- .cols -------------------------------------------------------------------
        fd = $fopen(cols_file, "r");
        if (fd == 0) begin
            $display("ERROR: cannot open %0s", cols_file);
            meta_ok = 1'b0;
        end else begin
            ncols = 0; sum_in = 0; sum_out = 0;
            while (!$feof(fd) && ncols < MAXCOLS) begin
                key = 0; kind = 0;
                r = $fscanf(fd, "%s %d %s", key, w, kind);
                if (r == 3) begin
                    col_name[ncols] = key;
                    col_w[ncols] = w;
                    col_out[ncols] = (kind == "out");
                    if (kind == "out") sum_out = sum_out + w; else sum_in = sum_in + w;
                    ncols = ncols + 1;
                end
            end
            $fclose(fd);
            // ports plus framing: _sentinel (4, in) and _check (W_CHECK, out)
            if (sum_in != 4 + W_IN || sum_out != W_OUT + W_CHECK) begin
                $display("ERROR: %0s: %0d input and %0d output bits, this testbench has %0d and %0d",
                         cols_file, sum_in - 4, sum_out - W_CHECK, W_IN, W_OUT);
                meta_ok = 1'b0;
            end
        end
        if (!meta_ok) begin
            $display("0 passed, 1 failed");
            $finish;
        end
        // ---- .hex: digits per line and line count, then framing ------------------------
        fd = $fopen(hex_file, "r");
        if (fd == 0) begin
            $display("ERROR: cannot open %0s", hex_file);
            $display("0 passed, 1 failed");
            $finish;
        end
        nlines = 0;
        while (!$feof(fd) && corrupt == 0) begin
            text = 0;
            r = $fgets(text, fd);
            if (r > 0) begin
                len = r;
                if (text[7:0] == 8'h0A) len = len - 1;
                if (len > 0 && text[15:8] == 8'h0D && text[7:0] == 8'h0A) len = len - 1;
                nlines = nlines + 1;
                if (len != W_LINE / 4) begin
                    $display("CORRUPT: %0s line %0d: %0d characters, expected %0d hex digits (truncated line or wrong width)",
                             hex_file, nlines, len, W_LINE / 4);
                    fail_corrupt;
                end
            end
        end
        $fclose(fd);
        if (corrupt == 0 && nlines != n_cycles) begin
            $display("CORRUPT: %0s has %0d lines, %0s records cycles %0d", hex_file, nlines, meta_file, n_cycles);
            fail_corrupt;
        end
        if (corrupt == 0)
            $readmemh(hex_file, mem, 0, n_cycles - 1);
        for (i = 0; i < n_cycles && corrupt == 0; i = i + 1) begin
            line = mem[i];
            if (^line === 1'bx) begin
                $display("CORRUPT: %0s line %0d: not a hex word of %0d digits", hex_file, i + 1, W_LINE / 4);
                fail_corrupt;
            end else if (line[W_LINE-1 -: 4] != 4'hA) begin
                $display("CORRUPT: %0s line %0d: sentinel digit %h, expected A (truncated or wrong width; %0d digits per line)",
                         hex_file, i + 1, line[W_LINE-1 -: 4], W_LINE / 4);
                fail_corrupt;
            end else if (digit_xor(line) != 4'h0) begin
                $display("CORRUPT: %0s line %0d: check digit wrong (XOR of the digits %h, expected 0)",
                         hex_file, i + 1, digit_xor(line));
                fail_corrupt;
            end
        end
        if (corrupt != 0) begin
            $display("0 passed, %0d failed", n_cycles);
            $finish;
        end
        // ---- replay ------------------------------------------------------------------------
        for (i = 0; i < n_cycles; i = i + 1) begin
            line = mem[i];
            @(negedge clk);
            vin = line[W_LINE-5 -: W_IN];
            line_nx = mem[(i + 1 < n_cycles) ? i + 1 : i];
            vin_nx = line_nx[W_LINE-5 -: W_IN];
            exp_out = line[W_CHECK +: W_OUT];
            @(posedge clk);
            #1;
            got = vout;
            diff = (got ^ exp_out) & mask;
            if (diff !== {W_OUT{1'b0}}) begin
                failed = failed + 1;
                if (reported < max_report) begin
                    reported = reported + 1;
                    // name the differing columns: the output columns in .cols order, from the top
                    lo = W_OUT;
                    for (k = 0; k < ncols; k = k + 1) begin
                        if (col_out[k] && col_name[k] != "_check") begin
                            lo = lo - col_w[k];
                            cm = (col_w[k] >= 64) ? ~64'd0 : ((64'd1 << col_w[k]) - 64'd1);
                            if ((({64'd0, diff} >> lo) & cm) !== 64'd0)
                                $display("MISMATCH cycle %0d column %0s: expected %0h got %0h",
                                         i, col_name[k], ({64'd0, exp_out} >> lo) & cm,
                                         ({64'd0, got} >> lo) & cm);
                        end
                    end
                end
            end else begin
                passed = passed + 1;
            end
        end
        $display("%0d passed, %0d failed", passed, failed);
        $finish;
    end
