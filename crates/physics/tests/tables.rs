//! Table choices (size and pocket cut) as a player writes them, and the WPA sizes they give
//! (moved from `table.rs` to keep that file under the size limit).

use billiards_physics::table::{INCH, PocketCut, Table, TableChoice, TableSize};

#[test]
fn table_choices_parse_print_and_give_the_wpa_sizes() {
    for text in ["7ft", "8ft", "9ft", "9ft-tight", "7ft-wide"] {
        let c: TableChoice = text.parse().unwrap();
        assert_eq!(c.to_string(), text);
    }
    assert_eq!("8ft-wpa".parse::<TableChoice>().unwrap().to_string(), "8ft");
    assert_eq!(TableChoice::default().table(), Table::wpa_8ft());
    let t = "9ft-tight".parse::<TableChoice>().unwrap().table();
    assert_eq!((t.length, t.width), (100.0 * INCH, 50.0 * INCH));
    assert_eq!((t.corner_mouth, t.side_mouth), (4.0 * INCH, 5.0 * INCH));
    assert_eq!(Table::wpa_7ft().length, 78.0 * INCH);
    for bad in ["6ft", "9ft-huge", "", "9"] {
        let e = bad.parse::<TableChoice>().unwrap_err();
        assert!(e.contains("expected"), "{e}");
    }
    for c in TableSize::ALL {
        let t = TableChoice {
            size: c,
            pockets: PocketCut::Tight,
        }
        .table();
        assert!(t.validate(0.028575).is_ok());
    }
}
