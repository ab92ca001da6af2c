#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| tmc429_fuzz::script(data));
