use gaitlab::config::presets;
use gaitlab::model::walk::Walker;
fn main() {
    let params = presets::params("default").unwrap().unwrap();
    let mut w = Walker::new(&params).unwrap();
    let mut s = 0.0;
    for _ in 0..400_000 { w.advance(1.0 / 60.0); s += w.pose().position[0].x; }
    println!("{s}");
}
