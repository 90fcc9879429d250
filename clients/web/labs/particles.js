export default {id: 'particles', title: 'particles', mount(main) { main.textContent = 'particles'; }};
