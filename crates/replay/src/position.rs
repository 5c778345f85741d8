//! `billiards-cli position`: a position's code from its JSON (`encode`), and its JSON from a
//! code (`decode`), through [`billiards_rules::Position`].

use billiards_rules::Position;
use clap::Subcommand;
use std::path::PathBuf;

/// To and from position codes.
#[derive(Subcommand, Debug)]
pub enum PositionCmd {
    /// Print the code of the position in a JSON file (`-` reads standard input).
    Encode {
        /// The position as JSON: `{"game", "table", "balls": [{"number", "position"}],
        /// "params"?, "shot"?}`, as `decode` prints it.
        file: PathBuf,
    },
    /// Print the position of a code as JSON.
    Decode {
        /// The code.
        code: String,
    },
}

/// Runs one `position` subcommand.
pub fn run(cmd: PositionCmd) -> Result<(), String> {
    match cmd {
        PositionCmd::Encode { file } => {
            let text = if file.as_os_str() == "-" {
                std::io::read_to_string(std::io::stdin()).map_err(|e| format!("stdin: {e}"))?
            } else {
                std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?
            };
            let p: Position = serde_json::from_str(&text)
                .map_err(|e| format!("{}: not a position: {e}", file.display()))?;
            let code = p.encode().map_err(|e| format!("{}: {e}", file.display()))?;
            println!("{code}");
        }
        PositionCmd::Decode { code } => {
            let p = Position::decode(&code).map_err(|e| e.to_string())?;
            let json = serde_json::to_string_pretty(&p).map_err(|e| e.to_string())?;
            println!("{json}");
        }
    }
    Ok(())
}
