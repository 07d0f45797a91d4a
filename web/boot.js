// The page's bootstrap (docs/plots.md, "The interactive page"): three.js
// and the page's module are held as text, in script elements of type
// text/plain, so that the one file opens offline; each becomes a module (a
// blob URL), its imports pointed at the others' URLs.
(function () {
  'use strict';
  function fail(e) {
    const box = document.getElementById('ic-error');
    box.textContent = 'The page could not start: ' + (e && e.message ? e.message : e);
    box.hidden = false;
    console.error(e);
  }
  function text(id) {
    return document.getElementById(id).textContent;
  }
  function moduleUrl(source) {
    return URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
  }
  // every import of `from` in source, now from `to`; an error if there is none
  function redirect(source, from, to, where) {
    const pattern = "from '" + from + "'";
    if (source.indexOf(pattern) < 0)
      throw new Error(where + ' does not import ' + from + ': another three.js version?');
    return source.split(pattern).join("from '" + to + "'");
  }
  try {
    const core = moduleUrl(text('ic-three-core'));
    const three = moduleUrl(redirect(text('ic-three-module'), './three.core.js', core, 'three.module.js'));
    const orbit = moduleUrl(redirect(text('ic-orbit-controls'), 'three', three, 'OrbitControls.js'));
    let page = redirect(text('ic-page'), 'three', three, 'page.js');
    page = redirect(page, 'three/addons/controls/OrbitControls.js', orbit, 'page.js');
    import(moduleUrl(page)).catch(fail);
  } catch (e) {
    fail(e);
  }
})();
