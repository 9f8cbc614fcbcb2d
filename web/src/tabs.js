// The page's tabs (WAI-ARIA tabs): each shows its panels and hides the
// others'; the arrow keys, Home and End move between them. A tab's view, if
// any, is told when it is shown or hidden (its work starts when first shown).

const $ = (id) => document.getElementById(id);

/**
 * `tabs`: [{ tab: the button's id, name: the body's data-tab, panels: [the
 * ids of the sections it shows], view: an object with show(visible), or null }…].
 */
export function setupTabs(tabs) {
  const all = [...new Set(tabs.flatMap((t) => t.panels))];
  const select = (chosen, focus) => {
    for (const t of tabs) {
      const on = t === chosen;
      $(t.tab).setAttribute("aria-selected", String(on));
      $(t.tab).tabIndex = on ? 0 : -1;
    }
    for (const id of all) $(id).hidden = !chosen.panels.includes(id);
    document.body.dataset.tab = chosen.name;
    for (const t of tabs) t.view?.show(t === chosen);
    if (focus) $(chosen.tab).focus();
  };
  tabs.forEach((t, i) => {
    $(t.tab).addEventListener("click", () => select(t));
    $(t.tab).addEventListener("keydown", (e) => {
      const to = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: tabs.length - 1 }[e.key];
      if (to === undefined) return;
      e.preventDefault();
      select(tabs[(to + tabs.length) % tabs.length], true);
    });
  });
}
