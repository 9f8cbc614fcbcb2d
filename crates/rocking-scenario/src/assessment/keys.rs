//! The documentation of every key of `[site]` and `[assessment]`, printed by
//! `rocking keys --markdown` after the scenario's keys; a test checks that it
//! lists exactly the keys the parser takes.

use crate::keys::{key, KeyDoc, KeyKind::*};

/// Every key of `[site]` and `[assessment]`, in the order of the reference page.
pub const ASSESSMENT_KEY_DOCS: &[KeyDoc] = &[
    key(
        "site.code",
        Text,
        "",
        "\"ntc2018\"",
        "\"ntc2018\" or \"ec8\"",
        "The code: NTC 2018 spectra and limit states SLO–SLC, or EN 1998-1 spectra with EN 1998-3's DL, SD, NC.",
        "\"ntc2018\"",
    )
    .choices(&["ntc2018", "ec8"]),
    key(
        "site.soil",
        Text,
        "",
        "required",
        "\"A\" to \"E\"",
        "Subsoil category (NTC 2018 §3.2.2) or ground type (EN 1998-1 §3.1.2).",
        "\"B\"",
    )
    .choices(&["A", "B", "C", "D", "E"]),
    key(
        "site.topography",
        Text,
        "",
        "\"T1\"",
        "\"T1\" to \"T4\"; NTC only; not with ST",
        "Topographic category: ST = 1.0, 1.2, 1.2, 1.4 (NTC 2018 Tab. 3.2.V).",
        "\"T2\"",
    )
    .choices(&["T1", "T2", "T3", "T4"]),
    key(
        "site.ST",
        Number,
        "",
        "from topography",
        "[1.0, 1.4]; NTC only",
        "A given topographic amplification ST instead of the category's.",
        "1.1",
    ),
    key(
        "site.spectrum_type",
        Number,
        "",
        "1",
        "1 or 2; EC8 only",
        "EN 1998-1 spectrum type (1: Ms > 5.5, 2: smaller earthquakes).",
        "1",
    )
    .placeholder("1"),
    key(
        "site.grid",
        Text,
        "",
        "none",
        "\"ntc2018\", or a file in the layout of NTC Allegato B; NTC only; not with the limit states' tables",
        "Hazard grid: the site parameters of SLD, SLV, SLC interpolated at lon, lat (NTC Allegato A). \"ntc2018\" is the official grid (Tabella 1 of Allegato B, 10,751 nodes), held by the program; else a file relative to the assessment file.",
        "\"ntc2018\"",
    ),
    key(
        "site.island",
        Text,
        "",
        "none",
        "\"G1\" to \"G5\"; NTC only; not with grid, lon, lat, nor the limit states' tables",
        "A group of small islands outside the grid, with Tabella 2's values of Allegato B: G1 Sardinia, Tuscan archipelago, Egadi, Pantelleria, Lampedusa, Linosa, Ponza, Palmarola, Zannone; G2 Ventotene, Santo Stefano; G3 Ustica, Tremiti; G4 Alicudi, Filicudi; G5 Panarea, Stromboli, Lipari, Vulcano, Salina.",
        "\"G1\"",
    ),
    key(
        "site.lon",
        Number,
        "°",
        "required with grid",
        "inside the grid",
        "Longitude of the site (degrees east); for `rocking inventory`, each tower's `lon` column instead.",
        "14.43",
    ),
    key(
        "site.lat",
        Number,
        "°",
        "required with grid",
        "inside the grid",
        "Latitude of the site (degrees north); for `rocking inventory`, each tower's `lat` column instead.",
        "41.04",
    ),
    key(
        "site.VN",
        Number,
        "years",
        "50",
        "> 0; with grid or island",
        "Nominal life VN (NTC 2018 §2.4.1); TR = −VN CU / ln(1 − P_VR).",
        "50",
    )
    .shown("VN", "nominal life")
    .placeholder("50"),
    key(
        "site.CU",
        Number,
        "",
        "1.0",
        "> 0; with grid or island",
        "Coefficient of use CU of the class of use (NTC 2018 §2.4.3).",
        "1.5",
    )
    .shown("CU", "coefficient of use")
    .placeholder("1"),
    key(
        "site.SLO",
        Table,
        "",
        "none",
        "NTC only; not with grid",
        "Site parameters of SLO: ag (g), F0, Tc_star (s).",
        "{ ag = 0.05, F0 = 2.5, Tc_star = 0.28 }",
    ),
    key(
        "site.SLD",
        Table,
        "",
        "none",
        "NTC only; not with grid",
        "Site parameters of SLD: ag (g), F0, Tc_star (s).",
        "{ ag = 0.062, F0 = 2.52, Tc_star = 0.30 }",
    ),
    key(
        "site.SLV",
        Table,
        "",
        "none",
        "NTC only; not with grid",
        "Site parameters of SLV: ag (g), F0, Tc_star (s).",
        "{ ag = 0.155, F0 = 2.47, Tc_star = 0.36 }",
    ),
    key(
        "site.SLC",
        Table,
        "",
        "none",
        "NTC only; not with grid",
        "Site parameters of SLC: ag (g), F0, Tc_star (s).",
        "{ ag = 0.196, F0 = 2.50, Tc_star = 0.37 }",
    ),
    key(
        "site.DL",
        Table,
        "",
        "none",
        "EC8 only",
        "Design ground acceleration of DL: ag = γI agR (g).",
        "{ ag = 0.08 }",
    ),
    key(
        "site.SD",
        Table,
        "",
        "none",
        "EC8 only",
        "Design ground acceleration of SD: ag = γI agR (g).",
        "{ ag = 0.20 }",
    ),
    key(
        "site.NC",
        Table,
        "",
        "none",
        "EC8 only",
        "Design ground acceleration of NC: ag = γI agR (g).",
        "{ ag = 0.30 }",
    ),
    key(
        "site.<LS>.ag",
        Number,
        "g",
        "required",
        "(0, 2]",
        "Peak ground acceleration on rock of the limit state (EC8: γI agR).",
        "0.155",
    ),
    key(
        "site.<LS>.F0",
        Number,
        "",
        "required (NTC)",
        "> 0",
        "Maximum spectral amplification on rock F0.",
        "2.47",
    ),
    key(
        "site.<LS>.Tc_star",
        Number,
        "s",
        "required (NTC)",
        "> 0",
        "Tc*, the period that fixes TC = CC Tc*.",
        "0.36",
    )
    .shown("Tc*", "Tc*"),
    key(
        "assessment.confidence_factor",
        Number,
        "",
        "1.35",
        "> 0; >= 1 for rocking assess",
        "Confidence factor FC, dividing the capacity's accelerations (LC1: 1.35, LC2: 1.2, LC3: 1).",
        "1.35",
    )
    .shown("FC", "confidence factor")
    .placeholder("1.35"),
    key(
        "assessment.knowledge_level",
        Text,
        "",
        "none (FC as given, else 1.35)",
        "\"LC1\", \"LC2\" or \"LC3\"",
        "Knowledge level of the building (Circolare 2019 §C8.5.4): sets FC to 1.35, 1.2 or 1 unless confidence_factor is given.",
        "\"LC2\"",
    )
    .shown("LC", "knowledge level")
    .choices(&["LC1", "LC2", "LC3"]),
    key(
        "assessment.q",
        Number,
        "",
        "2.0",
        "> 0",
        "Behaviour factor q of the linear kinematic check.",
        "2.0",
    )
    .placeholder("2"),
    key(
        "assessment.capacity",
        Text,
        "",
        "\"linear\"",
        "\"linear\" or \"exact\"",
        "Capacity curve: the Circolare's linear a*(d), or the rigid block's exact one.",
        "\"exact\"",
    )
    .choices(&["linear", "exact"]),
    key(
        "assessment.verdict_method",
        Text,
        "",
        "the most refined computed",
        "\"linear_kinematic\", \"nonlinear_kinematic\" or \"nonlinear_dynamic\" (with records)",
        "The method whose check carries the verdict of SLV and SLC (without it: non-linear dynamic with a record set, else non-linear kinematic); the others are reported as information.",
        "\"nonlinear_kinematic\"",
    )
    .choices(&["linear_kinematic", "nonlinear_kinematic", "nonlinear_dynamic"]),
    key(
        "assessment.accept_incompatible_set",
        Boolean,
        "",
        "false",
        "true or false",
        "Lets a dynamic check on a record set whose mean spectrum leaves the band 0.90–1.30 of the code's (NTC 2018 §3.2.3.6) carry the verdict, with a warning; without it such a check is reported not valid.",
        "true",
    ),
    key(
        "assessment.records",
        List,
        "",
        "none (no dynamic check)",
        "glob patterns matching at least one file, or tables { name, text } (a record's file name and content); 3 or more records to fit",
        "The record set of the dynamic checks, relative to the assessment file (or given as text, as the page gives the files picked); format guessed.",
        "[\"records/*.AT2\"]",
    ),
    key(
        "assessment.units",
        Text,
        "",
        "\"g\"",
        "\"g\", \"m/s2\" or \"cm/s2\"",
        "Units of the acceleration column of the set's CSV records, as ground.units (AT2 and ESM files carry their own).",
        "\"cm/s2\"",
    )
    .placeholder("g")
    .choices(&["g", "m/s2", "cm/s2"]),
    key(
        "assessment.dt",
        Number,
        "s",
        "the CSV's time column",
        "> 0",
        "Time step of the set's CSV records that have one acceleration column, as ground.dt.",
        "0.01",
    ),
    key(
        "assessment.period_range",
        List,
        "s",
        "[0.15, max(2.0, T_SLC)]",
        "0 < from < to, inside the spectra's periods",
        "Periods over which each record is fitted to the spectrum and the set's mean is checked (0.90–1.30).",
        "[0.15, 4.0]",
    ),
    key(
        "assessment.free_after",
        Number,
        "s",
        "10.0",
        ">= 0",
        "Seconds run after the end of each record in the dynamic checks.",
        "10.0",
    )
    .placeholder("10"),
    key(
        "assessment.lambda",
        Table,
        "",
        "{ from = 0.05, to = 3.0, step = 0.05 }",
        "0 < from < to, step > 0",
        "The scan of the record set's multiplier λ in the dynamic checks.",
        "{ from = 0.1, to = 2.0, step = 0.1 }",
    ),
    key(
        "assessment.support",
        Table,
        "",
        "none (the support's own values)",
        "with a [support]; one table per ultimate limit state: SLV, SLC (EC8: SD, NC)",
        "The support's values at an ultimate limit state (Circolare 2019 §C8.7.1.2.1.4: a masonry building's period grows by 50–100% and its damping reaches 10–20%); the damage state keeps the support's own.",
        "{ SLV = { period_factor = 1.5, damping = 0.10 } }",
    )
    .off_form(),
    key(
        "assessment.support.<LS>.period_factor",
        Number,
        "",
        "1",
        "> 0",
        "Every period of the support multiplied by it at the limit state.",
        "1.5",
    )
    .off_form(),
    key(
        "assessment.support.<LS>.damping",
        Number,
        "",
        "the support's own",
        "(0, 1)",
        "Every damping ratio of the support at the limit state (a fraction of critical).",
        "0.10",
    )
    .off_form(),
    key(
        "support.mass",
        Number,
        "kg",
        "required with [support]",
        "> 0",
        "Mass m_s of the elastic support the tower stands on (the church, the shaft), its whole mass. With it the checks take the floor spectrum of its top (Circolare 2019 §C7.2.3; EN 1998-1 eq. 4.25).",
        "1.5e6",
    )
    .off_form(),
    key(
        "support.period",
        Number,
        "s",
        "required (or [[support.mode]])",
        "> 0",
        "Period of the support alone (without the tower and the blocks on it), its one mode.",
        "0.35",
    )
    .off_form(),
    key(
        "support.damping",
        Number,
        "",
        "0.05",
        "[0, 1); > 0 in an assessment",
        "Damping ratio of the support's one mode, a fraction of critical.",
        "0.05",
    )
    .off_form(),
    key(
        "support.shape",
        Text,
        "",
        "\"sdof\"",
        "\"sdof\" (Γ = 1, m_eff = m_s), \"linear\" (Γ = 1.5, m_eff = 0.75 m_s) or \"cantilever\" (Γ = 1.5660, m_eff = 0.6131 m_s)",
        "The shape of the support's one mode: its participation factor Γ (the shape 1 where the tower stands) and effective mass.",
        "\"cantilever\"",
    )
    .off_form(),
    key(
        "support.mode",
        Table,
        "",
        "none (one mode from period, damping, shape)",
        "1 to 6 tables [[support.mode]]; not with period, damping, shape",
        "The support's modes one by one (sweeps and inventory columns name them support.mode.1.period, …).",
        "[{ period = 0.35, participation = 1.566, effective_mass = 0.613 }]",
    )
    .off_form(),
    key(
        "support.mode.<k>.period",
        Number,
        "s",
        "required",
        "> 0",
        "Period T_k of the support's mode k.",
        "0.35",
    )
    .off_form(),
    key(
        "support.mode.<k>.damping",
        Number,
        "",
        "0.05",
        "[0, 1); > 0 in an assessment",
        "Damping ratio ζ_k of mode k, a fraction of critical.",
        "0.05",
    )
    .off_form(),
    key(
        "support.mode.<k>.participation",
        Number,
        "",
        "required",
        "not 0",
        "Participation factor Γ_k of mode k, its shape normalised to 1 where the tower stands.",
        "1.566",
    )
    .off_form(),
    key(
        "support.mode.<k>.effective_mass",
        Number,
        "",
        "required",
        "(0, 1]; the modes' sum at most 1",
        "Effective mass of mode k, a fraction of support.mass.",
        "0.613",
    )
    .off_form(),
];

#[cfg(test)]
mod tests {
    use super::ASSESSMENT_KEY_DOCS;
    use crate::assessment::{AssessmentFile, ASSESSMENT_KEYS, NTC_STATE_KEYS, SITE_KEYS, SUPPORT_STATE_KEYS};
    use crate::support::{SUPPORT_KEYS, SUPPORT_MODE_KEYS};
    use std::path::Path;

    /// The choices the page's form offers are those the parser takes: a value
    /// outside them is refused with the parser's own list, which names them in order.
    #[test]
    fn the_choices_are_the_parsers() {
        let base = "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n[site]\nsoil = \"B\"\n[site.SLD]\nag = 0.062\nF0 = 2.52\nTc_star = 0.30\n[assessment]\n";
        let mut checked = 0;
        for doc in ASSESSMENT_KEY_DOCS.iter().filter(|d| !d.choices.is_empty()) {
            let (section, name) = doc.key.split_once('.').unwrap_or_default();
            let text = |value: &str| {
                let file = base
                    .replace(&format!("{name} = \"B\"\n"), "")
                    .replace(&format!("[{section}]\n"), &format!("[{section}]\n{name} = \"{value}\"\n"));
                // EC8's limit states are DL, SD, NC, each with its ag alone.
                if value == "ec8" {
                    file.replace("[site.SLD]\nag = 0.062\nF0 = 2.52\nTc_star = 0.30\n", "[site.DL]\nag = 0.062\n")
                } else {
                    file
                }
            };
            for choice in doc.choices {
                let parsed = AssessmentFile::from_toml_str(&text(choice), Path::new("a.toml"));
                assert!(parsed.is_ok(), "{} = {choice}: {parsed:?}", doc.key);
            }
            let e = AssessmentFile::from_toml_str(&text("zz"), Path::new("a.toml"))
                .err()
                .map(|e| e.to_string())
                .unwrap_or_default();
            // Each choice named in the error, in order, after the value refused.
            let mut rest = e.split_once("zz").map_or("", |(_, r)| r);
            for choice in doc.choices {
                let at = rest.find(choice).unwrap_or_else(|| panic!("{}: {choice} not in {e}", doc.key));
                rest = &rest[at + choice.len()..];
            }
            checked += 1;
        }
        assert_eq!(checked, 7);
    }

    #[test]
    fn documents_exactly_the_keys_the_parser_takes() {
        let mut documented: Vec<String> = ASSESSMENT_KEY_DOCS.iter().map(|k| k.key.to_string()).collect();
        let mut parsed: Vec<String> = SITE_KEYS.iter().map(|k| format!("site.{k}")).collect();
        parsed.extend(NTC_STATE_KEYS.iter().map(|k| format!("site.<LS>.{k}")));
        parsed.extend(ASSESSMENT_KEYS.iter().map(|k| format!("assessment.{k}")));
        parsed.extend(SUPPORT_STATE_KEYS.iter().map(|k| format!("assessment.support.<LS>.{k}")));
        parsed.extend(SUPPORT_KEYS.iter().map(|k| format!("support.{k}")));
        parsed.extend(SUPPORT_MODE_KEYS.iter().map(|k| format!("support.mode.<k>.{k}")));
        documented.sort();
        parsed.sort();
        assert_eq!(documented, parsed);
    }
}
