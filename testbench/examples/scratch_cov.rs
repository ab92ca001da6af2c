use tmc429_testbench::{run, Config};
use tmc429_testbench::signals::Compare;
use tmc429_testbench::stimulus::Profile;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let chip = a[1].parse::<tmc429_model::Chip>().unwrap();
    let mut cfg = Config::new(chip, a[2].parse().unwrap(), a[3].parse().unwrap());
    cfg.profile = Profile::Motion;
    cfg.compare = Compare(0);
    let out = run(&cfg).unwrap();
    print!("{}", out.summary());
    print!("{}", out.coverage.table());
}
