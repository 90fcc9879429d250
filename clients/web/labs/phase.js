export default {id: 'phase', title: 'phase', mount(main) { main.textContent = 'phase'; }};
