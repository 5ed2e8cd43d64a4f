/* The Dawson-integral table (seakeeping/green/dawson_integral_table.h) embedded as bytes: the file
   HULLOPT_DAWSON_TABLE_FILE, written when hullopt is built by hullopt_make_dawson_table
   (seakeeping/CMakeLists.txt), read-only data mapped from the executable (pages are loaded as they are used). */
#ifndef HULLOPT_DAWSON_TABLE_FILE
#error "HULLOPT_DAWSON_TABLE_FILE: the table file written by hullopt_make_dawson_table (seakeeping/CMakeLists.txt)"
#endif
__asm__(".section .rodata\n"
        ".balign 64\n"
        ".globl hullopt_dawson_integral_table\n"
        ".hidden hullopt_dawson_integral_table\n"
        ".type hullopt_dawson_integral_table, @object\n"
        "hullopt_dawson_integral_table:\n"
        ".incbin \"" HULLOPT_DAWSON_TABLE_FILE "\"\n"
        ".size hullopt_dawson_integral_table, . - hullopt_dawson_integral_table\n"
        ".globl hullopt_dawson_integral_table_end\n"
        ".hidden hullopt_dawson_integral_table_end\n"
        "hullopt_dawson_integral_table_end:\n"
        ".previous\n");
