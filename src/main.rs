//! The billiards game (placeholder until the game lands).

fn main() {
    println!("billiards: the game is not built yet; see README.md");
}
