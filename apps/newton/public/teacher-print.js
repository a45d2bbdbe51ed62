/* global window, document */
// The teacher pages' "Print the worksheet" button: prints only the worksheet and its answer key
// (teacher.css hides the rest while body has the class), then shows the whole page again.
for (const button of document.querySelectorAll('button[data-print="worksheet"]')) {
  button.addEventListener('click', () => {
    document.body.classList.add('worksheet-only');
    window.print();
  });
}
window.addEventListener('afterprint', () => document.body.classList.remove('worksheet-only'));
